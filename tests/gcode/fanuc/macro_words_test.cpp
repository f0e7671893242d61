// Issue 12 §2: the Fanuc words real macros use (docs/fanuc.md §7, "Words
// of real macros"): a bare G53, G31 skip, the look-ahead modes and G09,
// codes usina cannot run named as unsupported, #3003/#3004 and the
// interface input signals #1000-#1015/#1032.
#include <utility>

#include <gtest/gtest.h>

#include "fanuc_test_support.hpp"

namespace usina::gcode {
namespace {

using core::Code;
using fanuc_test::run_fanuc;

// `text` with the parameters a var file gives.
std::unique_ptr<dialect_test::Run> run_with_vars(const std::string& text,
                                                 const std::vector<std::pair<int, double>>& vars) {
  auto r = std::make_unique<dialect_test::Run>();
  const std::uint32_t id = r->sources.add(core::SourceFile::from_string("test.nc", text));
  const Dialect* d = find_dialect("fanuc");
  OptionValues values = default_options(*d);
  auto runner =
      d->make_runner(RunContext{r->sources, InterpOptions{}, std::move(values), r->path, r->diags});
  for (const auto& [index, value] : vars)
    runner->set_parameter(index, value);
  r->ok = runner->run(id);
  return r;
}

TEST(FanucMacroWords, BareG53MovesNothing) {
  auto r = run_fanuc("G0 X1. Y2.\nG53\n#100 = #5001\nG0 X[#100 + 1.]\nG1 Y3. F100.\nG53\nM30\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  ASSERT_EQ(r->ends().size(), 3u);
  fanuc_test::expect_end(*r, {2, 3, 0});
}

TEST(FanucMacroWords, G53WithAxisWordsStillMovesInMachineCoordinates) {
  auto r = run_fanuc("G10 L2 P1 X5.\nG54 G0 X1.\nG53 X1.\nM30\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  ASSERT_EQ(r->ends().size(), 2u);
  EXPECT_NEAR(r->ends()[0].x, 6.0, 1e-9);
  EXPECT_NEAR(r->ends()[1].x, 1.0, 1e-9);
}

TEST(FanucMacroWords, G31SkipIsAProbeMoveAndKeepsTheGroupOneMode) {
  auto r = run_fanuc("G0 X0 Y0 Z0\nG1 X1. F100.\nG31 X10.\n#100 = #5061\nX20.\nG0 X[#100]\nM30\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  const auto probes = r->all<canon::Probe>();
  ASSERT_EQ(probes.size(), 1u);
  EXPECT_NEAR(probes[0].to.x, 10.0, 1e-9);
  // Not tripped, as LinuxCNC's stand-alone G38.2: the stop 0.254 mm short
  // is the skip position #5061.
  const auto feeds = r->all<canon::Feed>();
  ASSERT_EQ(feeds.size(), 2u);  // X1., then X20. in G01, not a second probe
  EXPECT_NEAR(feeds[1].to.x, 20.0, 1e-9);
  fanuc_test::expect_end(*r, {10.0 - 0.254, 0, 0});  // G0 X#5061
}

TEST(FanucMacroWords, G31WithGroupOneCodeLeavesThatMode) {
  auto r = run_fanuc("G0 X0 Y0 Z0\nF100.\nG00 G31 X5.\nX8.\nM30\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  EXPECT_EQ(r->all<canon::Probe>().size(), 1u);
  const auto traverses = r->all<canon::Traverse>();
  ASSERT_EQ(traverses.size(), 2u);  // X0, then X8. in G00
  EXPECT_NEAR(traverses[1].to.x, 8.0, 1e-9);
}

TEST(FanucMacroWords, G31TakesP1ToP4) {
  auto r = run_fanuc("G1 F100.\nG31 P1 X1.\nG31 P4 X2.\nM30\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  EXPECT_EQ(r->all<canon::Probe>().size(), 2u);
  auto bad = run_fanuc("G1 F100.\nG31 P7 X1.\nM30\n");
  EXPECT_EQ(bad->first_error(), Code::BadWordValue);
}

TEST(FanucMacroWords, G31InACannedCycleIsAnError) {
  auto r = run_fanuc("G0 Z10.\nG81 X0 Y0 Z-1. R1. F100.\nG31 X10.\nM30\n");
  EXPECT_EQ(r->first_error(), Code::NotAllowedInMode) << r->first_error_text();
}

TEST(FanucMacroWords, LookAheadModesAndExactStopHaveNoGeometricEffect) {
  auto r = run_fanuc(
      "G05.1 Q1\nG0 X1.\nG05.1 Q0\nG05 P10000\nG1 X2. F100.\nG05 P0\nG08 P1\nG09 G1 X3.\n"
      "G08 P0\nM30\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  ASSERT_EQ(r->ends().size(), 3u);
  fanuc_test::expect_end(*r, {3, 0, 0});
  EXPECT_TRUE(r->all<canon::Dwell>().empty());
  EXPECT_TRUE(r->all<canon::Spline>().empty());
  EXPECT_FALSE(r->has(Code::IntegerCoordinate));  // G05.1's Q1 is no distance
}

TEST(FanucMacroWords, LookAheadModeValuesOutsideOnOffAreNamed) {
  auto q = run_fanuc("G05.1 Q3\nM30\n");
  EXPECT_EQ(q->first_error(), Code::Unsupported);
  EXPECT_NE(q->first_error_text().find("G05.1 Q3"), std::string::npos) << q->first_error_text();
  auto missing = run_fanuc("G08\nM30\n");
  EXPECT_EQ(missing->first_error(), Code::MissingWord);
}

TEST(FanucMacroWords, CodesUsinaCannotRunAreUnsupportedByName) {
  const std::pair<const char*, const char*> cases[] = {
      {"G68.2 X0 Y0 Z0 I0 J45. K0\n", "G68.2 (tilted working plane)"},
      {"G43.4 H1\n", "G43.4 (tool centre point control, type 1)"},
      {"G43.5 H1\n", "G43.5 (tool centre point control, type 2)"},
      {"G53.1\n", "G53.1 (tool axis direction control)"},
      {"G07.1 C10.\n", "G07.1 (cylindrical interpolation)"},
      {"G41.1 X1.\n", "G41.1 (normal direction control)"},
  };
  for (const auto& [program, name] : cases) {
    auto r = run_fanuc(std::string(program) + "M30\n");
    EXPECT_EQ(r->first_error(), Code::Unsupported) << program << r->first_error_text();
    EXPECT_NE(r->first_error_text().find(name), std::string::npos) << r->first_error_text();
    EXPECT_NE(r->first_error_text().find("not supported"), std::string::npos);
  }
}

TEST(FanucMacroWords, SuppressionBitsAreWritableAndReadBack) {
  auto r = run_fanuc("#3003 = 3\n#3004 = 7\nG0 X#3003 Y#3004\n#3003 = 0\nG0 Z#3003\nM30\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  fanuc_test::expect_end(*r, {3, 7, 0});
  auto bad = run_fanuc("#3004 = 8\nM30\n");
  EXPECT_EQ(bad->first_error(), Code::ValueOutOfRange);
}

TEST(FanucMacroWords, InterfaceInputsReadZeroUnlessAVarFileSetsThem) {
  auto r = run_fanuc("G0 X#1000 Y#1015 Z#1032\nM30\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  fanuc_test::expect_end(*r, {0, 0, 0});
  auto set = run_with_vars("G0 X#1000 Y#1003 Z#1032\nM30\n", {{1000, 1}, {1003, 1}});
  EXPECT_TRUE(set->ok) << set->first_error_text();
  fanuc_test::expect_end(*set, {1, 1, 9});
  auto word = run_with_vars("G0 X#1001 Y#1002 Z#1015\nM30\n", {{1032, 32770}});
  EXPECT_TRUE(word->ok) << word->first_error_text();
  fanuc_test::expect_end(*word, {1, 0, 1});
}

TEST(FanucMacroWords, InterfaceInputsCannotBeWritten) {
  auto r = run_fanuc("#1003 = 1\nM30\n");
  EXPECT_EQ(r->first_error(), Code::ReadOnlyParameter);
  EXPECT_NE(r->first_error_text().find("input signal"), std::string::npos);
}

}  // namespace
}  // namespace usina::gcode
