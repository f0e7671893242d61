// `usina simulate --target-dxf FILE --target LAYER=Z`: a drawing's depths
// against what the program cut (docs/simulate.md, "Target depths").
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/files.hpp"
#include "support/usina_process.hpp"

namespace usina::test {
namespace {

// A DXF of four LINEs on `layer` round the square [x0, x0 + side]².
std::string square_dxf(const std::string& layer, double x0, double side) {
  std::string dxf = "0\nSECTION\n2\nENTITIES\n";
  const double x[5] = {x0, x0 + side, x0 + side, x0, x0};
  const double y[5] = {x0, x0, x0 + side, x0 + side, x0};
  for (int k = 0; k < 4; ++k) {
    dxf += "0\nLINE\n8\n" + layer + "\n10\n" + std::to_string(x[k]) + "\n20\n" +
           std::to_string(y[k]) + "\n30\n0\n11\n" + std::to_string(x[k + 1]) + "\n21\n" +
           std::to_string(y[k + 1]) + "\n31\n0\n";
  }
  return dxf + "0\nENDSEC\n0\nEOF\n";
}

// Zigzag passes 2 mm apart over X10..20 at Z-2 with a 6 mm end mill, from
// Y10 up to `last_y`.
std::string zigzag(double last_y) {
  std::string p = "T1 M6\nG0 X10 Y10 Z1\nG1 Z-2 F300\n";
  bool right = true;
  for (double y = 10; y <= last_y + 1e-9; y += 2) {
    p += "G1 Y" + std::to_string(y) + "\nG1 X" + (right ? "20" : "10") + "\n";
    right = !right;
  }
  return p + "G0 Z5\nM30\n";
}

usina::test::Run simulate(const TempDir& dir, const std::string& program,
                          const std::string& extra) {
  return usina("simulate " + quote(program) +
               " --stock box:40x30x10 --resolution 0.1 --tool-shape 1=flat/6 -o " +
               quote(dir.path("r.json")) + " " + extra);
}

TEST(SimulateTargetCli, APocketCutToItsDepthMeetsItsTarget) {
  TempDir dir;
  const std::string dxf = dir.write("part.dxf", square_dxf("POCKET", 10, 10));
  const usina::test::Run r = simulate(dir, dir.write("p.ngc", zigzag(20)),
                                      "--target-dxf " + quote(dxf) + " --target POCKET=-2");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err.find("W_MATERIAL_ABOVE_TARGET"), std::string::npos) << r.err;
  const auto j = nlohmann::json::parse(dir.read("r.json"));
  ASSERT_EQ(j["targets"].size(), 1u);
  EXPECT_EQ(j["targets"][0]["layer"], "POCKET");
  EXPECT_NEAR(j["targets"][0]["area_mm2"].get<double>(), 100.0, 2.5);
  EXPECT_EQ(j["targets"][0]["above_mm2"].get<double>(), 0.0);
  EXPECT_FALSE(j["targets"][0].contains("code"));
}

TEST(SimulateTargetCli, WhatThePocketLeftIsAWarningWithItsPlace) {
  // The passes stop at Y14: a 6 mm tool reaches Y17, the square goes to Y20.
  TempDir dir;
  const std::string dxf = dir.write("part.dxf", square_dxf("POCKET", 10, 10));
  const usina::test::Run r = simulate(dir, dir.write("p.ngc", zigzag(14)),
                                      "--target-dxf " + quote(dxf) + " --target POCKET=-2");
  EXPECT_EQ(r.status, 0) << r.err;  // a warning
  EXPECT_NE(r.err.find("warning[W_MATERIAL_ABOVE_TARGET]: layer POCKET (Z-2)"), std::string::npos)
      << r.err;
  const auto j = nlohmann::json::parse(dir.read("r.json"));
  const auto& t = j["targets"][0];
  EXPECT_NEAR(t["above_mm2"].get<double>(), 30.0, 2.5);  // Y17..20 of X10..20
  EXPECT_NEAR(t["most_above_mm"].get<double>(), 2.0, 1e-4);
  EXPECT_GT(t["most_at"][1].get<double>(), 17.0);
  EXPECT_EQ(t["code"], "W_MATERIAL_ABOVE_TARGET");
  // A deeper target is not met by the full pocket either.
  const usina::test::Run deeper = simulate(dir, dir.write("q.ngc", zigzag(20)),
                                           "--target-dxf " + quote(dxf) + " --target POCKET=-2.5");
  EXPECT_NE(deeper.err.find("up to 0.500 mm"), std::string::npos) << deeper.err;
}

TEST(SimulateTargetCli, BadTargetsAreUsageErrors) {
  TempDir dir;
  const std::string dxf = dir.write("part.dxf", square_dxf("POCKET", 10, 10));
  const std::string open_dxf = dir.write("open.dxf",
                                         "0\nSECTION\n2\nENTITIES\n0\nLINE\n8\nSLOT\n10\n0\n"
                                         "20\n0\n30\n0\n11\n5\n21\n0\n31\n0\n0\nENDSEC\n0\nEOF\n");
  const std::string prog = dir.write("p.ngc", zigzag(20));
  const std::string d = " --target-dxf " + quote(dxf);
  for (const std::string& bad :
       {std::string("--target POCKET=-2"),  // no drawing
        d,                                  // no layer
        d + " --target POCKET", d + " --target =-2", d + " --target POCKET=x",
        d + " --target POCKET=nan", d + " --target POCKET=1e300",
        d + " --target NOSUCH=-2",  // no closed contour there
        d + " --target POCKET=-2 --target-tolerance -1",
        " --target-dxf " + quote(open_dxf) + " --target SLOT=-1",
        " --target-dxf " + quote(dir.path("missing.dxf")) + " --target POCKET=-1"}) {
    const usina::test::Run r = simulate(dir, prog, bad);
    EXPECT_EQ(r.status, 2) << bad << "\n" << r.err;
    EXPECT_NE(r.err.find("error"), std::string::npos) << bad;
  }
}

TEST(SimulateTargetCli, TheTargetDrawingIsNeverWrittenOver) {
  TempDir dir;
  const std::string text = square_dxf("POCKET", 10, 10);
  const std::string dxf = dir.write("part.dxf", text);
  const usina::test::Run r =
      usina("simulate " + quote(dir.write("p.ngc", zigzag(20))) +
            " --stock box:40x30x10 --tool-shape 1=flat/6 --target-dxf " + quote(dxf) +
            " --target POCKET=-2 -o " + quote(dxf + ".png") + " --height-map " + quote(dxf));
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(dir.read("part.dxf"), text);
}

}  // namespace
}  // namespace usina::test
