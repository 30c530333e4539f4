#pragma once
// The diagnosis's figures at the size campaigns are run (docs/figures.md, "At size"): what the
// gap-per-drop and residual figures draw is chosen by how many drops and conditions they hold,
// from plain rows, so the choice and the data written are tested without simulating a drop.
//  - Gap per drop: up to kMaxBarsPerPanel drops a panel, a bar pair per drop; more, and a bar
//    pair per condition (its replicates' mean, their range as whiskers, the held-out count in the
//    tic) up to kMaxBarsPerPanel conditions; more still, a scatter of each drop's NRMSE with the
//    effect against without it, the diagonal drawn, the worst few named.
//  - Residuals: up to kMaxResidualDropsDrawn held-out drops a panel, every sample; more, the
//    median and the 5-95 % band over time bins.
#include <array>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace touchdown::gap {

inline constexpr size_t kMaxBarsPerPanel = 25;
inline constexpr size_t kMaxResidualDropsDrawn = 10;
inline constexpr size_t kNamedWorstDrops = 5;  // named in the scatter layout
inline constexpr int kResidualBins = 60;

// One drop in the gap-per-drop figure: its force NRMSE before and after, the sensor-noise floor.
struct GapRow {
  std::string drop_label;       // short drop id
  std::string condition_label;  // "flat FJS-1 LP 1.2 m/s" (no comma): its replicates share it
  std::string condition_key;    // the fit's ConditionKey
  bool held_out = false;
  double before = 0.0, after = 0.0, floor = 0.0;
};

enum class GapLayout { kPerDrop, kByCondition, kScatter };
GapLayout ChooseGapLayout(const std::vector<GapRow>& rows);

// Writes data/gap_<atmosphere>.csv in the columns of the layout it chooses (nullopt, and no file,
// when `rows` is empty).
std::optional<GapLayout> WriteGapPanelData(const std::vector<GapRow>& rows, const std::string& atmosphere,
                                           const std::filesystem::path& dir);
// The gap-per-drop figure: vacuum and air panels (nullopt: a placeholder), each in its layout.
std::string GapPerDropFigure(const std::string& aug_title, const std::array<std::optional<GapLayout>, 2>& panels,
                             bool any_worse);

// A held-out drop's force residual at one sample, base and with the effect (normalised).
struct ResidualSample {
  double t_s = 0.0, base = 0.0, augmented = 0.0;
};
// One time bin of a panel's band: the 5th, 50th and 95th percentiles of each model's residual.
struct ResidualBand {
  double t_ms = 0.0;
  std::array<double, 3> base{}, augmented{};
  size_t samples = 0;
};
// Bins of equal width over the samples' time range; a bin of fewer than 5 samples is left out.
// Percentiles by linear interpolation between order statistics (deterministic: sorted copies).
std::vector<ResidualBand> ResidualBands(const std::vector<ResidualSample>& samples, int bins = kResidualBins);

// data/residual_bands_<atmosphere>.csv: t_ms, each model's 5/50/95 % and the bin's samples.
void WriteResidualBands(const std::vector<ResidualBand>& bands, const std::string& atmosphere,
                        const std::filesystem::path& dir);

// What each residual panel (vacuum, air) draws.
enum class ResidualLayout { kNone, kSamples, kBands };
struct ResidualPanels {
  std::array<ResidualLayout, 2> layout{ResidualLayout::kNone, ResidualLayout::kNone};
  std::array<size_t, 2> drops{0, 0};
  // One scale on every panel (so base and effect, vacuum and air compare by eye): of the samples
  // drawn, or of the bands' 5-95 % where bands are drawn.
  double t_lo_ms = 0.0, t_hi_ms = 1.0, r_lo = -1.0, r_hi = 1.0;
};
std::string ResidualFigure(const std::string& aug_title, const ResidualPanels& panels);

}  // namespace touchdown::gap
