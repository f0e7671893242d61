// Issue 12 §2: a Fanuc control runs its own M codes; any other goes to the
// machine's logic and is handed on as a machine_code op (traced, drawn
// nowhere, written back by posts), unless the machine_m_codes option lists
// the machine's and the code is not among them.
#include <gtest/gtest.h>

#include "fanuc_test_support.hpp"

namespace usina::gcode {
namespace {

using core::Code;
using fanuc_test::run_fanuc;

std::vector<int> machine_codes(const dialect_test::Run& r) {
  std::vector<int> out;
  for (const canon::MachineCode& m : r.all<canon::MachineCode>())
    out.push_back(m.code);
  return out;
}

TEST(FanucMachineCodes, MCodesNotTheControlsOwnAreHandedOn) {
  auto r = run_fanuc("M29 S500\nM11\nM262\nG0 X1.\nM30\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  EXPECT_FALSE(r->has(Code::UnknownMCode));
  EXPECT_EQ(machine_codes(*r), (std::vector<int>{29, 11, 262}));
}

TEST(FanucMachineCodes, LinuxCncsMCodesHaveNoLinuxCncMeaning) {
  // M72/M73 (modal state), M61 (tool number) are LinuxCNC's; on a Fanuc
  // they are the machine's.
  auto r = run_fanuc("G91\nM73\nM72\nM61\nG0 X1.\nX1.\nM30\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  EXPECT_EQ(machine_codes(*r), (std::vector<int>{73, 72, 61}));
  ASSERT_EQ(r->ends().size(), 2u);
  EXPECT_NEAR(r->ends()[1].x, 2.0, 1e-9);  // still G91: M72 restored nothing
}

TEST(FanucMachineCodes, AfterTheBlocksMoveBeforeTheProgramEnd) {
  auto r = run_fanuc("G0 X1. M29\nM11 M30\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  const auto& ops = r->path.ops();
  ASSERT_GE(ops.size(), 4u);
  EXPECT_TRUE(std::holds_alternative<canon::Traverse>(ops[0].kind));
  EXPECT_TRUE(std::holds_alternative<canon::MachineCode>(ops[1].kind));
  EXPECT_TRUE(std::holds_alternative<canon::MachineCode>(ops[2].kind));
  EXPECT_TRUE(std::holds_alternative<canon::ProgramEnd>(ops.back().kind));
  EXPECT_EQ(ops[1].src.line, 1u);
  EXPECT_EQ(ops[2].src.line, 2u);
}

TEST(FanucMachineCodes, TheControlsOwnStayTheControls) {
  auto r = run_fanuc("S1000 M3\nM8\nM9\nM5\nM30\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  EXPECT_TRUE(machine_codes(*r).empty());
  EXPECT_FALSE(r->all<canon::Spindle>().empty());
}

TEST(FanucMachineCodes, AListOfTheMachinesMakesAnyOtherAnError) {
  auto ok = run_fanuc("M29\nM262\nM30\n", {}, {"machine_m_codes=29,262"});
  EXPECT_TRUE(ok->ok) << ok->first_error_text();
  EXPECT_EQ(machine_codes(*ok), (std::vector<int>{29, 262}));
  auto bad = run_fanuc("M29\nM11\nM30\n", {}, {"machine_m_codes=29,262"});
  EXPECT_FALSE(bad->ok);
  EXPECT_EQ(bad->first_error(), Code::UnknownMCode);
}

TEST(FanucMachineCodes, TheListOptionTakesWholeNumbersOnly) {
  const Dialect* d = find_dialect("fanuc");
  const auto values = resolve_options(*d, {"machine_m_codes=29,11,262"});
  ASSERT_TRUE(values.has_value()) << values.error();
  EXPECT_EQ(values->at("machine_m_codes"), "29,11,262");
  EXPECT_FALSE(resolve_options(*d, {"machine_m_codes=29,,11"}).has_value());
  EXPECT_FALSE(resolve_options(*d, {"machine_m_codes=M29"}).has_value());
  EXPECT_FALSE(resolve_options(*d, {"machine_m_codes="}).has_value());
  EXPECT_FALSE(resolve_options(*d, {"machine_m_codes=29,123456789"}).has_value());
}

TEST(FanucMachineCodes, PAndQGoWithTheMachinesCode) {
  auto r = run_fanuc("M59 P2\nM140 P123 Q4\nG04 P1000\nM30\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  const auto codes = r->all<canon::MachineCode>();
  ASSERT_EQ(codes.size(), 2u);
  EXPECT_EQ(codes[0].code, 59);
  EXPECT_EQ(codes[0].p, 2.0);
  EXPECT_FALSE(codes[0].q.has_value());
  EXPECT_EQ(codes[1].code, 140);
  EXPECT_EQ(codes[1].p, 123.0);
  EXPECT_EQ(codes[1].q, 4.0);
  ASSERT_EQ(r->all<canon::Dwell>().size(), 1u);
  EXPECT_NEAR(r->all<canon::Dwell>()[0].s, 1.0, 1e-12);  // G04's P stays G04's
}

TEST(FanucMachineCodes, PGoesWithTheMachinesCodeInAMoveBlock) {
  auto r = run_fanuc("G90 G1 X10. F100. M59 P2\nG4 P500 M60\nM30\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  const auto codes = r->all<canon::MachineCode>();
  ASSERT_EQ(codes.size(), 2u);
  EXPECT_EQ(codes[0].p, 2.0);
  EXPECT_FALSE(codes[1].p.has_value());  // G04's P stays G04's
  ASSERT_EQ(r->all<canon::Dwell>().size(), 1u);
  EXPECT_NEAR(r->all<canon::Dwell>()[0].s, 0.5, 1e-12);
}

// Haas's M97 P is a local subprogram call, something to run: usina does
// not run it, and says so by name.
TEST(FanucMachineCodes, HaasLocalSubprogramCallIsUnsupportedByName) {
  auto r = run_fanuc("M97 P123\nM30\nN123\nM99\n");
  EXPECT_FALSE(r->ok);
  EXPECT_EQ(r->first_error(), Code::Unsupported);
  EXPECT_NE(r->first_error_text().find("M97"), std::string::npos) << r->first_error_text();
  EXPECT_TRUE(machine_codes(*r).empty());
}

TEST(FanucMachineCodes, AListedM97IsTheMachines) {
  auto r = run_fanuc("M97 P123\nM30\n", {}, {"machine_m_codes=97"});
  EXPECT_TRUE(r->ok) << r->first_error_text();
  EXPECT_EQ(machine_codes(*r), (std::vector<int>{97}));
}

}  // namespace
}  // namespace usina::gcode
