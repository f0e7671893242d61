// Every dialect's G/M table is data the runner reads by index
// (gcode/code_table.hpp): the interpreter knows a code, its group and how
// it runs from its dialect's table, not from a switch of its own.
#include "gcode/code_table.hpp"

#include <algorithm>
#include <stdexcept>

#include <gtest/gtest.h>

#include "canon/toolpath.hpp"
#include "gcode/dialect.hpp"
#include "gcode/fanuc/engine.hpp"
#include "gcode/interp/codes.hpp"
#include "gcode/interp/interpreter.hpp"
#include "support/dialect_run.hpp"

namespace usina::gcode {
namespace {

using dialect_test::run_in;

TEST(CodeTable, EveryDialectHasItsTable) {
  for (const Dialect* d : all_dialects())
    EXPECT_FALSE(d->codes.empty()) << d->name;
}

TEST(CodeTable, TheFirstEntryOfACodeIsTheOneFound) {
  const std::vector<CodeEntry> codes = {{'G', 10, 1, "group_step"}, {'G', 10, 2, "user_m"}};
  const InterpCodes t = interp_code_table("test", codes);
  ASSERT_NE(t.find('G', 10), nullptr);
  EXPECT_EQ(t.find('G', 10)->entry, &codes[0]);
  EXPECT_EQ(t.find('G', 10)->handler, CodeRun::GroupStep);
  EXPECT_EQ(t.find('M', 10), nullptr);
  EXPECT_EQ(t.find('G', -10), nullptr);
  EXPECT_EQ(t.find('G', kMaxCodeTenths + 1), nullptr);
  EXPECT_EQ(t.find('X', 10), nullptr);
  EXPECT_TRUE(t.index().has_integer('G', 1));
  EXPECT_FALSE(t.index().has_integer('G', 2));
}

TEST(CodeTable, RanksFollowTheGroupNumbers) {
  const std::vector<CodeEntry> codes = {
      {'G', 10, 50, "group_step"}, {'G', 170, 12, "group_step"}, {'M', 30, 2, "group_step"}};
  const CodeIndex i("test", codes, 9990);
  EXPECT_EQ(i.ranks(), 3);
  EXPECT_EQ(i.rank(2), 0);
  EXPECT_EQ(i.rank(12), 1);
  EXPECT_EQ(i.rank(50), 2);
  EXPECT_EQ(i.rank(20), 2);  // a group it lacks: the next larger one's rank
}

TEST(CodeTable, AWrongTableIsRefusedWhenItIsMade) {
  const std::vector<CodeEntry> no_handler = {{'G', 10, 1, "no_such_handler"}};
  EXPECT_THROW(interp_code_table("test", no_handler), std::logic_error);
  const std::vector<CodeEntry> no_group = {{'G', 10, kGGroups, "group_step"}};
  EXPECT_THROW(interp_code_table("test", no_group), std::logic_error);
  const std::vector<CodeEntry> no_code = {{'G', kMaxCodeTenths + 1, 1, "group_step"}};
  EXPECT_THROW(interp_code_table("test", no_code), std::logic_error);
  const std::vector<CodeEntry> no_letter = {{'T', 10, 1, "group_step"}};
  EXPECT_THROW(interp_code_table("test", no_letter), std::logic_error);
}

// LinuxCNC's groups (rs274ngc/codes.cpp), as its interp_array.cc numbers them.
TEST(CodeTable, Rs274ngcTableHasLinuxcncGroups) {
  const InterpCodes& t = rs274ngc_code_table();

  const struct {
    char letter;
    int code;
    int group;
  } cases[] = {
      {'G', 10, kGroupMotion},       {'G', 382, kGroupMotion}, {'G', 40, kGroupNonModal},
      {'G', 921, kGroupNonModal},    {'G', 171, -1},           {'G', 432, kGroupToolLength},
      {'G', 593, kGroupCoordSystem}, {'G', 641, -1},           {'M', 30, kMGroupSpindle},
      {'M', 610, kMGroupToolChange}, {'M', 1990, kMGroupUser}, {'M', 2000, -1},
      {'M', 730, kMGroupModalState}, {'M', 20, kMGroupStop}};

  for (const auto& c : cases) {
    const InterpCodes::Code* code = t.find(c.letter, c.code);
    if (c.group < 0) {
      EXPECT_EQ(code, nullptr) << c.letter << c.code;
      continue;
    }
    ASSERT_NE(code, nullptr) << c.letter << c.code;
    EXPECT_EQ(code->entry->group, c.group) << c.letter << c.code;
  }
  EXPECT_EQ(t.find('M', 1000)->handler, CodeRun::UserM);
  EXPECT_EQ(t.find('G', 711)->handler, CodeRun::Unsupported);
}

// The interpreter runs what its dialect's table has: a table without G2 makes
// G2 an unknown code, with the same interpreter.
TEST(CodeTable, TheInterpreterKnowsTheCodesOfItsDialectsTable) {
  std::vector<CodeEntry> codes = linuxcnc_codes();
  std::erase_if(codes, [](const CodeEntry& e) { return e.letter == 'G' && e.code == 20; });
  const InterpCodes table = interp_code_table("test", codes);
  core::SourceManager sources;
  core::DiagnosticList diags;
  canon::Toolpath path;
  const std::uint32_t id =
      sources.add(core::SourceFile::from_string("t.ngc", "G1 X10 F100\nG2 X20 R5\nM2\n"));
  Interpreter interp(sources, {}, path, diags, nullptr, DialectRules{.codes = &table});
  EXPECT_FALSE(interp.run(id));
  ASSERT_FALSE(diags.all().empty());
  EXPECT_EQ(diags.all()[0].code, core::Code::UnknownGCode) << diags.all()[0].message;
  EXPECT_EQ(diags.all()[0].loc.line, 2u);
}

// Fanuc's table: the control's own M codes, its codes usina cannot run named.
TEST(CodeTable, FanucTableNamesTheControlsCodes) {
  const InterpCodes& t = fanuc::code_table();
  for (int m : {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 19, 30, 98, 99, 198})
    EXPECT_NE(t.find('M', m * 10), nullptr) << "M" << m;
  for (int m : {48, 60, 61, 62, 70, 72, 73, 100})
    EXPECT_EQ(t.find('M', m * 10), nullptr) << "M" << m;
  ASSERT_NE(t.find('G', 721), nullptr);
  EXPECT_EQ(t.find('G', 721)->entry->what, "figure copying, rotation");
  EXPECT_EQ(t.find('G', 711), nullptr);  // LinuxCNC's G71.1: no Fanuc code
}

TEST(CodeTable, FanucLatheCyclesAreUnsupportedOnItsOwnTerms) {
  auto r = run_in("fanuc", "O1\nG70 P10 Q20\nM30\n");
  EXPECT_EQ(r->first_error(), core::Code::Unsupported);
  EXPECT_NE(r->first_error_text().find("G70 (finishing cycle of a lathe)"), std::string::npos)
      << r->first_error_text();
  EXPECT_EQ(r->first_error_text().find("LinuxCNC"), std::string::npos) << r->first_error_text();
}

TEST(CodeTable, FanucM198IsTheControlsCodeUsinaCannotRun) {
  auto r = run_in("fanuc", "O1\nM198 P1234\nM30\n");
  EXPECT_EQ(r->first_error(), core::Code::Unsupported);
  EXPECT_NE(r->first_error_text().find("M198 (subprogram call from external memory)"),
            std::string::npos)
      << r->first_error_text();
}

TEST(CodeTable, Rs274ngcLatheCycleMessageIsKept) {
  auto r = run_in("rs274ngc", "G71.1 Q1\nM2\n");
  EXPECT_EQ(r->first_error(), core::Code::Unsupported);
  EXPECT_EQ(r->first_error_text(),
            "G71.1 (LinuxCNC's lathe roughing/finishing cycle) is not supported yet");
}

}  // namespace
}  // namespace usina::gcode
