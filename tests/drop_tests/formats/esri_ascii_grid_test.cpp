// ReadEsriAsciiGrid: georeference (corner and centre), rows north to south, windows by
// coordinates, and each refusal as one line naming the file, the line (row, column) and the reason.
#include "drop_tests/formats/esri_ascii_grid.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "rft/input_error.h"
#include "tests/scratch_dir_test.h"

namespace touchdown::io {
namespace {

class EsriAsciiGridTest : public testing_scratch::ScratchDirTest {
 protected:
  // The InputError's message for `text` read with `window`; "" if it reads.
  std::string Refusal(const std::string& text, const std::optional<RasterWindow>& window = {}) {
    const std::string path = Write("bad.asc", text);
    try {
      ReadEsriAsciiGrid(path, window);
    } catch (const InputError& e) {
      const std::string m = e.what();
      EXPECT_EQ(m.find('\n'), std::string::npos) << m;  // one line
      EXPECT_EQ(m.rfind(path + ": ", 0), 0u) << m;      // naming the file first
      return m.substr(path.size() + 2);
    }
    return "";
  }
};

// 4 columns x 3 rows, heights 10 * row-from-north + column.
constexpr const char* kHeader = "ncols 4\nnrows 3\nxllcorner 100\nyllcorner 200\ncellsize 2\nNODATA_value -9999\n";
constexpr const char* kRows = "0 1 2 3\n10 11 12 13\n20 21 22 23\n";

TEST_F(EsriAsciiGridTest, ReadsCellCentresSouthRowFirst) {
  const rft::HeightGrid g = ReadEsriAsciiGrid(Write("site.asc", std::string(kHeader) + kRows));
  EXPECT_EQ(g.nx, 4);
  EXPECT_EQ(g.ny, 3);
  EXPECT_EQ(g.cell_m, 2.0);
  EXPECT_EQ(g.x0_m, 101.0);  // the lower-left cell's centre: corner + half a cell
  EXPECT_EQ(g.y0_m, 201.0);
  EXPECT_EQ(g.At(0, 0), 20.0);  // south-west: the file's last row, first column
  EXPECT_EQ(g.At(3, 2), 3.0);   // north-east: the file's first row, last column
  EXPECT_EQ(g.At(1, 1), 11.0);
}

TEST_F(EsriAsciiGridTest, CentreGeoreferenceCaseAndLineEndings) {
  const rft::HeightGrid g = ReadEsriAsciiGrid(
      Write("c.asc",
            "NCOLS 3\r\nNROWS 3\r\nXLLCENTER -1.5\r\nYLLCENTER 4\r\nCELLSIZE 0.5\r\n1 2 3\r\n4 5 6\r\n7 8 9\r\n\r\n"));
  EXPECT_EQ(g.x0_m, -1.5);
  EXPECT_EQ(g.y0_m, 4.0);
  EXPECT_EQ(g.At(0, 0), 7.0);
  EXPECT_EQ(g.At(2, 2), 3.0);
}

TEST_F(EsriAsciiGridTest, WindowKeepsTheNodesInsideIt) {
  // Node x: 101, 103, 105, 107; node y (south to north): 201, 203, 205.
  const std::string text =
      std::string("ncols 5\nnrows 4\nxllcorner 100\nyllcorner 200\ncellsize 2\nNODATA_value -9999\n") +
      "-9999 -9999 -9999 -9999 -9999\n0 1 2 3 -9999\n10 11 12 13 -9999\n20 21 22 23 -9999\n";
  const rft::HeightGrid g = ReadEsriAsciiGrid(
      Write("w.asc", text), RasterWindow{.x_min_m = 102.5, .y_min_m = 201.0, .x_max_m = 107.0, .y_max_m = 205.5});
  EXPECT_EQ(g.nx, 3);  // x 103, 105, 107 (107 on the edge counts)
  EXPECT_EQ(g.ny, 3);  // y 201, 203, 205
  EXPECT_EQ(g.x0_m, 103.0);
  EXPECT_EQ(g.y0_m, 201.0);
  EXPECT_EQ(g.At(0, 0), 21.0);
  EXPECT_EQ(g.At(2, 2), 3.0);
  // NODATA just outside the window is allowed; the whole raster is refused.
  EXPECT_EQ(Refusal(text),
            "line 7 (row 1, column 1): NODATA inside the raster (a terrain needs every height it interpolates)");
  EXPECT_EQ(Refusal(text, RasterWindow{.x_min_m = 103, .y_min_m = 201, .x_max_m = 109, .y_max_m = 205}),
            "line 8 (row 2, column 5): NODATA inside the window (a terrain needs every height it interpolates)");
}

struct RefusalCase {
  const char* what;
  std::string text;
  std::string message;
};

TEST_F(EsriAsciiGridTest, RefusesMalformedFilesWithOneLine) {
  const std::string h = kHeader;
  const std::vector<RefusalCase> cases = {
      {"missing key", "ncols 4\nnrows 3\nxllcorner 100\nyllcorner 200\n0 1 2 3\n", "header: missing key cellsize"},
      {"missing y", "ncols 4\nnrows 3\nxllcorner 1\ncellsize 1\n0 1 2 3\n",
       "header: missing key yllcorner (or yllcenter)"},
      {"twice", "ncols 4\nncols 4\n", "line 2: header key 'ncols' given twice"},
      {"unknown", "ncols 4\ndx 2\n",
       "line 2: unknown header key 'dx' (expected ncols, nrows, xllcorner or xllcenter, "
       "yllcorner or yllcenter, cellsize, NODATA_value; non-square cells are not supported)"},
      {"cell zero", "ncols 4\nnrows 3\nxllcorner 1\nyllcorner 1\ncellsize 0\n",
       "line 5: cellsize must be positive, got '0'"},
      {"cell negative", "cellsize -2\n", "line 1: cellsize must be positive, got '-2'"},
      {"cols fraction", "ncols 4.5\n", "line 1: 'ncols' must be a whole number from 1 to 1000000, got '4.5'"},
      {"header text", "ncols four\n", "line 1: 'ncols' must be a finite number, got 'four'"},
      {"short row", h + "0 1 2 3\n10 11 12\n20 21 22 23\n", "line 8 (row 2): has 3 values, expected ncols = 4"},
      {"long row", h + "0 1 2 3 4\n", "line 7 (row 1): has more than ncols = 4 values"},
      {"non-number", h + "0 1 2 3\n10 x1 12 13\n20 21 22 23\n", "line 8 (row 2, column 2): not a finite number: 'x1'"},
      {"nan", h + "0 1 2 3\n10 11 12 13\n20 21 nan 23\n", "line 9 (row 3, column 3): not a finite number: 'nan'"},
      {"missing rows", h + "0 1 2 3\n", "row 2: missing: the file ends after 1 of 3 rows"},
      {"extra rows", h + kRows + "1 2 3 4\n", "line 10: more data after the 3 rows nrows gives"},
      {"too few nodes", "ncols 2\nnrows 3\nxllcorner 0\nyllcorner 0\ncellsize 1\n1 2\n3 4\n5 6\n",
       "header: keeps 2 x 3 nodes; the interpolation needs at least 3 x 3"},
  };
  for (const RefusalCase& c : cases) EXPECT_EQ(Refusal(c.text), c.message) << c.what;
}

TEST_F(EsriAsciiGridTest, RefusesWindowsOutsideTheRaster) {
  const std::string text = std::string(kHeader) + kRows;  // node x 101..107, y 201..205
  EXPECT_EQ(Refusal(text, RasterWindow{.x_min_m = 99, .y_min_m = 201, .x_max_m = 105, .y_max_m = 205}),
            "window: x range 99.000000 to 105.000000 reaches outside the raster's cell centres, 101.000000 to "
            "107.000000");
  EXPECT_EQ(Refusal(text, RasterWindow{.x_min_m = 101, .y_min_m = 203, .x_max_m = 107, .y_max_m = 203}),
            "window: y range is empty: 203.000000 to 203.000000");
  EXPECT_EQ(Refusal(text, RasterWindow{.x_min_m = 101, .y_min_m = 201, .x_max_m = 104, .y_max_m = 205}),
            "window: keeps 2 x 3 nodes; the interpolation needs at least 3 x 3");
}

TEST_F(EsriAsciiGridTest, MissingFileIsOneLine) {
  try {
    ReadEsriAsciiGrid(Path("nowhere.asc"));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("nowhere.asc"), std::string::npos);
  }
}

}  // namespace
}  // namespace touchdown::io
