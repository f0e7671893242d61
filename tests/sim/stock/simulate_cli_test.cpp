// `usina simulate` as a user runs it: the seed 002 ellipse pocket at two DDA
// resolutions, the JSON report's fields, the files it writes, the bounds.
#include <cstring>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/files.hpp"
#include "support/usina_process.hpp"

namespace usina::test {
namespace {

nlohmann::json simulated(const TempDir& dir, const std::string& program, const std::string& extra) {
  const std::string report = dir.path("report.json");
  const usina::test::Run r =
      usina("simulate " + quote(program) +
            " --stock box:40x30x10 --resolution 0.1 --tool-shape 1=flat/6 -o " + quote(report) +
            " " + extra);
  EXPECT_EQ(r.status, 0) << r.err;
  return nlohmann::json::parse(dir.read("report.json"));
}

std::string ellipse(const TempDir& dir, const char* resolution) {
  const std::string out = dir.path(std::string("ellipse-") + resolution + ".ngc");
  const usina::test::Run r = usina(
      "gen ellipse-pocket --center 20,15 --rx 10 --ry 6 --depth 2 --step-down 2 --stepover 2 "
      "--tool-diameter 6 --resolution " +
      std::string(resolution) + " --post rs274ngc -o " + quote(out));
  EXPECT_EQ(r.status, 0) << r.err;
  return out;
}

TEST(SimulateCli, TheEllipsePocketDoesNotDependOnTheDdaResolution) {
  TempDir dir;
  const double coarse = simulated(dir, ellipse(dir, "0.1"), "")["removed_mm3"].get<double>();
  const double fine = simulated(dir, ellipse(dir, "0.001"), "")["removed_mm3"].get<double>();
  EXPECT_NEAR(fine, coarse, 1e-4 * coarse) << coarse << " " << fine;
  // The ellipse's area x depth (the tool reaches every point of the wall:
  // its radius is less than the least radius of curvature, 6²/10 = 3.6 mm).
  EXPECT_NEAR(fine, M_PI * 10.0 * 6.0 * 2.0, 0.002 * fine);
}

TEST(SimulateCli, TheReportHasTheIssuesFields) {
  TempDir dir;
  const std::string program =
      dir.write("p.ngc", "T1 M6\nG0 X5 Y5 Z1\nG1 Z-1 F100\nG1 X35\nG0 X5 Y20 Z-0.5\nG0 Z5\nM30\n");
  const usina::test::Run r =
      usina("simulate " + quote(program) +
            " --stock box:40x30x10 --resolution 0.1 --tool-shape 1=flat/6 -o " +
            quote(dir.path("r.json")) + " -o " + quote(dir.path("s.stl")) + " -o " +
            quote(dir.path("s.png")) + " --height-map " + quote(dir.path("h.png")));
  EXPECT_EQ(r.status, 1) << r.err;  // the rapid on line 5 cuts
  EXPECT_NE(r.err.find("E_RAPID_CUTS_STOCK"), std::string::npos) << r.err;
  const auto j = nlohmann::json::parse(dir.read("r.json"));
  ASSERT_TRUE(j.contains("removed_mm3"));
  ASSERT_TRUE(j["per_tool"].contains("1"));
  EXPECT_DOUBLE_EQ(j["per_tool"]["1"]["removed_mm3"].get<double>(), j["removed_mm3"].get<double>());
  ASSERT_EQ(j["checks"].size(), 1u);
  EXPECT_EQ(j["checks"][0]["code"], "E_RAPID_CUTS_STOCK");
  EXPECT_EQ(j["checks"][0]["line"], 5);
  EXPECT_TRUE(j["checks"][0].contains("message"));
  // A binary STL: 80 bytes, a count, 50 bytes a triangle.
  const std::string stl = dir.read("s.stl");
  ASSERT_GE(stl.size(), 84u);
  std::uint32_t n = 0;
  std::memcpy(&n, stl.data() + 80, 4);
  EXPECT_EQ(stl.size(), 84u + 50u * n);
  EXPECT_EQ(dir.read("s.png").substr(1, 3), "PNG");
  const std::string h = dir.read("h.png");
  ASSERT_GT(h.size(), 33u);
  EXPECT_EQ(h[24], 16);  // bit depth
  EXPECT_EQ(h[25], 0);   // greyscale
}

TEST(SimulateCli, BadInputsAreRefusedWithStatus2) {
  TempDir dir;
  const std::string program = dir.write("p.ngc", "G0 X1\nM30\n");
  for (const std::string& bad : {std::string("--stock box:0x1x1"), std::string("--stock box:1x1"),
                                 std::string("--stock box:10x10x10 --resolution nan"),
                                 std::string("--stock box:10x10x10 --resolution 0"),
                                 std::string("--stock box:10x10x10 --tool-shape 1=blob/6"),
                                 std::string("--stock box:10x10x10 --tool-shape 1=ball"),
                                 std::string("--stock box:10x10x10 -o out.txt")}) {
    const usina::test::Run r = usina("simulate " + quote(program) + " " + bad);
    EXPECT_EQ(r.status, 2) << bad << "\n" << r.err;
  }
  const usina::test::Run big =
      usina("simulate " + quote(program) + " --stock box:10000x10000x10 --resolution 0.01");
  EXPECT_EQ(big.status, 2);
  EXPECT_NE(big.err.find("E_STOCK_GRID_TOO_LARGE"), std::string::npos) << big.err;
  EXPECT_NE(big.err.find("1000000 x 1000000"), std::string::npos) << big.err;
}

}  // namespace
}  // namespace usina::test
