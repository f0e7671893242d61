// The grbl dialect on whole programs: tests/programs/grbl/ (whose README says
// what each must do), the modes a jog keeps, Grbl's start-up G0, homing,
// going on after an error or stopping there.
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "grbl_test_support.hpp"

namespace usina::gcode {
namespace {

using testing::run_grbl;

std::string program(const std::string& name) {
  std::ifstream f(std::string(USINA_TEST_DIR) + "/programs/grbl/" + name, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  EXPECT_FALSE(s.str().empty()) << name;
  return s.str();
}

void expect_at(const core::Vec3& got, const core::Vec3& want) {
  EXPECT_NEAR(got.x, want.x, 1e-6);
  EXPECT_NEAR(got.y, want.y, 1e-6);
  EXPECT_NEAR(got.z, want.z, 1e-6);
}

TEST(GrblPrograms, CleanFilesRunWithoutErrorsOrEndWarnings) {
  for (const char* name : {"cncjs_circle.gcode", "cncjs_circle_inch.gcode", "cncjs_g2_arc.gcode",
                           "jscut_tball_engrave_excerpt.gcode", "fusion_style_grbl_post.nc",
                           "probe_touch_plate.nc", "setup_settings_and_homing.nc"}) {
    auto r = run_grbl(program(name));
    EXPECT_TRUE(r->ok) << name;
    EXPECT_TRUE(r->errors().empty()) << name;
    EXPECT_FALSE(r->has(core::Code::NoProgramEnd)) << name;
    EXPECT_FALSE(r->has(core::Code::TextAfterProgramEnd)) << name;  // a '%' after M30 is no text
    EXPECT_FALSE(r->moves().empty()) << name;
  }
}

TEST(GrblPrograms, ErrorFileGivesEachLinesNumber) {
  // The number in each line's comment (tests/programs/grbl/grbl_errors.nc).
  auto r = run_grbl(program("grbl_errors.nc"));
  EXPECT_FALSE(r->ok);
  const std::vector<std::pair<std::uint32_t, int>> want = {
      {3, 22},  {4, 20},  {5, 1},   {6, 2},   {7, 25}, {8, 24},  {9, 28}, {10, 23}, {11, 34},
      {12, 36}, {13, 20}, {14, 20}, {15, 38}, {16, 4}, {17, 11}, {19, 3}, {20, 21}};
  EXPECT_EQ(r->errors(), want);
  // Going on: the M30 after the errors ends the program.
  ASSERT_FALSE(r->path.ops().empty());
  EXPECT_TRUE(std::holds_alternative<canon::ProgramEnd>(r->path.ops().back().kind));
}

TEST(GrblPrograms, FullCircleWithoutAxisWordsIsError26AndTheNextLinesRun) {
  // Grbl refuses G2 with no axis words (gcode.c: "[No axis words]"), so the
  // motion mode stays G1 and N55 X.75 / N56 Z.2 are straight feeds.
  auto r = run_grbl(program("cncjs_full_circle_without_xyz.gcode"));
  const std::vector<std::pair<std::uint32_t, int>> want = {{4, 26}, {10, 26}, {16, 26}};
  EXPECT_EQ(r->errors(), want);
  const auto m = r->moves();
  ASSERT_EQ(m.size(), 15u);
  EXPECT_EQ(m[8].first, "feed");  // N55
  expect_at(m[8].second, {0.75, -3.4, -0.5});
}

TEST(GrblPrograms, SettingsHomingAndJogs) {
  auto r = run_grbl(program("setup_settings_and_homing.nc"));
  const auto m = r->moves();
  ASSERT_EQ(m.size(), 5u);
  // $H: minus the $27 pull-off (1 mm) on each axis.
  EXPECT_EQ(m[0].first, "traverse");
  expect_at(m[0].second, {-1, -1, -1});
  EXPECT_EQ(m[2].first, "feed");  // $J=G91 X5 F500
  expect_at(m[2].second, {15, 10, -1});
  expect_at(m[3].second, {15, 10, -2});  // $J=G53 Z-2
  EXPECT_EQ(m[4].first, "traverse");     // G0 and G90 kept after the jogs
  expect_at(m[4].second, {0, 0, -2});
}

TEST(GrblPrograms, JogKeepsDistanceModeFeedAndMotion) {
  auto r = run_grbl("G1 X1 F100\n$J=G91 X5 F1000\n$J=G20 X1 F10\nY1\nG91 Y1\nG1 X1\n");
  EXPECT_TRUE(r->errors().empty());
  const auto m = r->moves();
  ASSERT_EQ(m.size(), 6u);
  expect_at(m[1].second, {6, 0, 0});
  expect_at(m[2].second, {25.4, 0, 0});  // the jog's G20 is the jog's only; absolute
  EXPECT_EQ(m[3].first, "feed");         // Y1: still G1 at F100, absolute
  expect_at(m[3].second, {25.4, 1, 0});
  expect_at(m[5].second, {26.4, 2, 0});
  const auto* f = std::get_if<canon::Feed>(&r->path.ops()[3].kind);
  ASSERT_NE(f, nullptr);
  EXPECT_DOUBLE_EQ(*f->f, 100.0);
}

TEST(GrblPrograms, StartsInG0) {
  // Grbl's start-up motion mode is G0 (the interpreter's is G80).
  auto r = run_grbl("X10 Y5\nG53 Z-1\n");
  EXPECT_TRUE(r->ok);
  const auto m = r->moves();
  ASSERT_EQ(m.size(), 2u);
  EXPECT_EQ(m[0].first, "traverse");
  expect_at(m[0].second, {10, 5, 0});
  expect_at(m[1].second, {10, 5, -1});
}

TEST(GrblPrograms, HomingNeedsSetting22) {
  auto off = run_grbl("$H\nG0 X1\n");
  EXPECT_EQ(off->errors(), (std::vector<std::pair<std::uint32_t, int>>{{1, 5}}));
  auto on = run_grbl("$22=1\n$27=2\nG20\n$H\nX1\n");
  EXPECT_TRUE(on->errors().empty());
  const auto m = on->moves();
  ASSERT_EQ(m.size(), 2u);
  expect_at(m[0].second, {-2, -2, -2});
  EXPECT_EQ(m[1].first, "traverse");
  expect_at(m[1].second, {25.4, -2, -2});
}

TEST(GrblPrograms, ARefusedLineSetsNothing) {
  // Grbl discards a refused line whole: its F is not set either.
  auto r = run_grbl("G2 X10 R2 F100\nG1 X1\n");
  const std::vector<std::pair<std::uint32_t, int>> want = {{1, 34}, {2, 22}};
  EXPECT_EQ(r->errors(), want);
}

TEST(GrblPrograms, StopOptionEndsAtTheFirstError) {
  const std::string text = "G0 X1\nG1 X2\nG0 X3\nG4\n";
  auto go_on = run_grbl(text);
  EXPECT_EQ(go_on->errors().size(), 2u);
  EXPECT_EQ(go_on->moves().size(), 2u);
  auto stop = run_grbl(text, {"after_error=stop"});
  EXPECT_EQ(stop->errors(), (std::vector<std::pair<std::uint32_t, int>>{{2, 22}}));
  EXPECT_EQ(stop->moves().size(), 1u);
  // An error only the interpreter finds stops there too.
  auto arc = run_grbl("G2 X10 Y0 R2 F100\nG0 X1\n", {"after_error=stop"});
  EXPECT_EQ(arc->errors(), (std::vector<std::pair<std::uint32_t, int>>{{1, 34}}));
  EXPECT_TRUE(arc->moves().empty());
}

TEST(GrblPrograms, InterpreterErrorsAreSkippedOneByOne) {
  // Two arcs the interpreter refuses; the blocks between and after still run.
  // The refused line 2 sets no F; hence F on a line of its own.
  auto r = run_grbl("F100\nG2 X10 R2\nG1 X1\nG2 X1 Y0 R3\nG1 Y5\n");
  const std::vector<std::pair<std::uint32_t, int>> want = {{2, 34}, {4, 33}};
  EXPECT_EQ(r->errors(), want);
  const auto m = r->moves();
  ASSERT_EQ(m.size(), 2u);
  expect_at(m[1].second, {1, 5, 0});
}

TEST(GrblPrograms, PercentLinesRealTimeCharactersAndTextAfterEnd) {
  auto r = run_grbl("%\nG0 X1 (stop!)\nM2\nG0 X5\n%\n");
  EXPECT_TRUE(r->ok);
  EXPECT_TRUE(r->has(core::Code::GrblWarning));
  EXPECT_TRUE(r->has(core::Code::TextAfterProgramEnd));
  ASSERT_EQ(r->moves().size(), 1u);
  auto mid = run_grbl("G0 X1 %\n");
  EXPECT_EQ(mid->errors(), (std::vector<std::pair<std::uint32_t, int>>{{1, 1}}));
}

TEST(GrblPrograms, MachineCommandsWarnAndDoNothing) {
  for (const char* line : {"$C", "$SLP", "$RST=$", "$RST=#", "$RST=*"}) {
    auto r = run_grbl(std::string(line) + "\nG0 X1\n");
    EXPECT_TRUE(r->has(core::Code::GrblWarning)) << line;
    EXPECT_TRUE(r->errors().empty()) << line;
    EXPECT_EQ(r->moves().size(), 1u) << line;
  }
}

TEST(GrblPrograms, BlockDeleteRunsTheBlock) {
  auto r = run_grbl("/G0 X7\n");
  ASSERT_EQ(r->moves().size(), 1u);
  expect_at(r->moves()[0].second, {7, 0, 0});
}

}  // namespace
}  // namespace usina::gcode
