#include "drop_tests/gap/gap_floor.h"

#include <algorithm>
#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/fisher_f.hpp>
#include <cmath>
#include <functional>
#include <map>

#include "drop_tests/gap/diagnose.h"

namespace touchdown::gap {

namespace {

// A condition's drops with a residual, and the samples they share (the shortest record's).
struct Condition {
  std::vector<const std::vector<double>*> residuals;
  size_t samples = 0;
};

std::map<std::string, Condition> Conditions(const FitProblem& p, const std::vector<DropGap>& gaps,
                                            const std::function<std::string(const FitDrop&)>& group) {
  std::map<std::string, std::map<std::string, Condition>> by;  // group -> condition
  std::map<std::string, Condition> out;
  for (size_t i = 0; i < p.drops.size() && i < gaps.size(); ++i) {
    if (gaps[i].failed || gaps[i].force_residual.empty()) continue;
    Condition& c = out[group(p.drops[i]) + "#" + ConditionKey(p.drops[i])];
    c.samples = c.residuals.empty() ? gaps[i].force_residual.size() : std::min(c.samples, gaps[i].force_residual.size());
    c.residuals.push_back(&gaps[i].force_residual);
  }
  return out;
}

// Sums over one condition: R |mean|^2 and sum_d |r_d - mean|^2, per sample compared.
void Sums(const Condition& c, double& lack, double& pure) {
  const size_t R = c.residuals.size(), L = c.samples;
  lack = pure = 0.0;
  if (L == 0) return;
  for (size_t i = 0; i < L; ++i) {
    double mean = 0.0;
    for (const std::vector<double>* r : c.residuals) mean += (*r)[i];
    mean /= double(R);
    lack += double(R) * mean * mean;
    for (const std::vector<double>* r : c.residuals) pure += ((*r)[i] - mean) * ((*r)[i] - mean);
  }
  lack /= double(L);
  pure /= double(L);
}

std::string CellOf(const FitDrop& d, const FitProblem& p) {
  return p.pads[d.pad].name + " / " + p.soils[d.soil].name + " / " + rft::AtmosphereName(d.atmosphere);
}

}  // namespace

GapFloor ComputeFloor(const FitProblem& p, const std::vector<DropGap>& gaps, double held_out_noise_ms) {
  GapFloor f;
  f.noise_ms = held_out_noise_ms;
  double pure = 0.0;
  for (const auto& [key, c] : Conditions(p, gaps, [](const FitDrop&) { return std::string(); })) {
    if (c.residuals.size() < 2) continue;
    double lack = 0.0, pe = 0.0;
    Sums(c, lack, pe);
    pure += pe;
    f.replicate_df += static_cast<int>(c.residuals.size()) - 1;
    ++f.conditions;
  }
  if (f.replicate_df > 0) f.replicate_ms = pure / f.replicate_df;
  f.from_replicates = f.replicate_df >= kMinPureErrorDf;
  // The pure error holds the noise too; where it reads lower (few replicates, a quiet stretch),
  // the noise stands: no model does better than the sensor.
  f.ms = f.from_replicates ? std::max(f.replicate_ms, f.noise_ms) : f.noise_ms;
  f.ms_upper = f.ms;
  if (f.from_replicates && f.replicate_ms > f.noise_ms)
    f.ms_upper = f.replicate_ms * f.replicate_df /
                 boost::math::quantile(boost::math::chi_squared(static_cast<double>(f.replicate_df)), 0.05);
  return f;
}

bool LowerFloorByCandidates(const FitProblem& p, const std::vector<const std::vector<DropGap>*>& candidate_gaps,
                            const std::vector<std::string>& names, GapFloor& floor) {
  if (!floor.from_replicates) return false;
  bool lowered = false;
  for (size_t k = 0; k < candidate_gaps.size(); ++k) {
    GapFloor f = ComputeFloor(p, *candidate_gaps[k], floor.noise_ms);
    if (!f.from_replicates || !(f.ms < floor.ms)) continue;
    f.model = names[k];
    floor = f;
    lowered = true;
  }
  return lowered;
}

std::vector<CellLackOfFit> LackOfFit(const FitProblem& p, const std::vector<DropGap>& gaps) {
  std::map<std::string, CellLackOfFit> cells;
  CellLackOfFit all;
  all.cell = "all";
  double all_lack = 0.0, all_pure = 0.0;
  int all_df = 0;
  std::map<std::string, std::pair<double, double>> sums;  // cell -> (lack, pure)
  std::map<std::string, int> df;
  for (const auto& [key, c] : Conditions(p, gaps, [&p](const FitDrop& d) { return CellOf(d, p); })) {
    const std::string cell = key.substr(0, key.find('#'));
    double lack = 0.0, pe = 0.0;
    Sums(c, lack, pe);
    CellLackOfFit& out = cells[cell];
    out.cell = cell;
    ++out.conditions;
    out.drops += static_cast<int>(c.residuals.size());
    sums[cell].first += lack;
    sums[cell].second += pe;
    df[cell] += static_cast<int>(c.residuals.size()) - 1;
  }
  std::vector<CellLackOfFit> out;
  const auto finish = [](CellLackOfFit& c, double lack, double pure, int df_pe) {
    c.lack_of_fit_ms = lack / std::max(c.conditions, 1);
    c.pure_error_ms = df_pe > 0 ? pure / df_pe : std::nan("");
    if (df_pe <= 0 || !(c.pure_error_ms > 0)) return false;
    c.F = c.lack_of_fit_ms / c.pure_error_ms;
    c.p_value = boost::math::cdf(boost::math::complement(boost::math::fisher_f(c.conditions, df_pe), c.F));
    return true;
  };
  for (auto& [name, c] : cells) {
    if (finish(c, sums[name].first, sums[name].second, df[name])) out.push_back(c);
    all.conditions += c.conditions, all.drops += c.drops;
    all_lack += sums[name].first, all_pure += sums[name].second, all_df += df[name];
  }
  if (finish(all, all_lack, all_pure, all_df)) out.push_back(all);
  return out;
}

}  // namespace touchdown::gap
