// The romi dialect's G/M table resolved once (romi/codes.hpp): every code
// found by index with its handler and its group's place in the order of
// execution; a table naming a handler nobody has is refused when it is
// made, not when a block uses the code.
#include "gcode/romi/codes.hpp"

#include <stdexcept>

#include <gtest/gtest.h>

#include "gcode/romi/engine.hpp"
#include "gcode/romi/services.hpp"

namespace usina::gcode::romi {
namespace {

TEST(RomiCodes, EveryCodeOfTheTableIsFoundWithItsHandler) {
  const Dialect& d = *find_dialect("romi");
  const CodeTable& t = code_table();
  for (const CodeEntry& e : d.codes) {
    const Code* c = t.find(e.letter, e.code);
    ASSERT_NE(c, nullptr) << code_name(e.letter, e.code);
    EXPECT_EQ(c->entry, d.find_code(e.letter, e.code)) << code_name(e.letter, e.code);
    EXPECT_EQ(c->handler, Translator::handler_named(e.handler)) << e.handler;
  }
}

TEST(RomiCodes, CodesOutsideTheTableAreNotFound) {
  const CodeTable& t = code_table();
  EXPECT_EQ(t.find('G', 180), nullptr);  // G18: not a romi code
  EXPECT_EQ(t.find('M', 980), nullptr);
  EXPECT_EQ(t.find('G', 11), nullptr);  // G1.1
  EXPECT_EQ(t.find('G', -10), nullptr);
  EXPECT_EQ(t.find('G', CodeTable::kMaxTenths + 1), nullptr);
  EXPECT_EQ(t.find('X', 10), nullptr);
}

TEST(RomiCodes, GroupsRunInTheOrderOfTheirNumbers) {
  const Dialect& d = *find_dialect("romi");
  const CodeTable& t = code_table();
  for (const CodeEntry& a : d.codes) {
    for (const CodeEntry& b : d.codes) {
      const int ra = t.find(a.letter, a.code)->rank;
      const int rb = t.find(b.letter, b.code)->rank;
      EXPECT_EQ(a.group < b.group, ra < rb)
          << code_name(a.letter, a.code) << " " << code_name(b.letter, b.code);
      EXPECT_EQ(a.group >= kAfterMoveGroup, ra >= t.first_after_move())
          << code_name(a.letter, a.code);
    }
  }
}

TEST(RomiCodes, TwoCodesOfOneGroupConflict) {
  const CodeTable& t = code_table();
  BlockCodes b;
  EXPECT_EQ(b.place(*t.find('G', 10)), nullptr);
  EXPECT_EQ(b.place(*t.find('G', 900)), nullptr);
  EXPECT_EQ(b.place(*t.find('G', 20)), t.find('G', 10));  // G02 after G01
  int runs = 0;
  int last_rank = -1;
  EXPECT_TRUE(b.each(0, t.ranks(), [&](const Code& c) {
    EXPECT_GT(c.rank, last_rank);
    last_rank = c.rank;
    return ++runs > 0;
  }));
  EXPECT_EQ(runs, 2);
  b.clear();
  EXPECT_TRUE(b.each(0, t.ranks(), [](const Code&) { return false; }));
}

TEST(RomiCodes, AHandlerNameNobodyHasIsRefusedWhenTheTableIsMade) {
  Dialect d;
  d.name = "romi-test";
  d.codes = {{'G', 10, 50, "motion"}, {'G', 20, 50, "no_such_handler"}};
  EXPECT_THROW(CodeTable(d, &Translator::handler_named, kAfterMoveGroup), std::logic_error);
  d.codes.pop_back();
  EXPECT_NO_THROW(CodeTable(d, &Translator::handler_named, kAfterMoveGroup));
}

TEST(RomiCodes, CodeNames) {
  EXPECT_EQ(code_name('G', 10), "G01");
  EXPECT_EQ(code_name('M', 300), "M30");
  EXPECT_EQ(code_name('G', 382), "G38.2");
}

TEST(RomiOptions, MissingOptionsTakeTheDialectsDefaults) {
  const Dialect& d = *find_dialect("romi");
  const Options o = Options::from(d, {});
  EXPECT_TRUE(o.lowercase_incremental);
  EXPECT_FALSE(o.typographic_dash_is_error);
  EXPECT_FALSE(o.motion_cancels_cycle);
  EXPECT_TRUE(o.comp_radius_from_register);
  const auto v = resolve_options(d, {"lowercase_incremental=off", "typographic_dash=error",
                                     "motion_cancels_cycle=on", "comp_radius=tool"});
  ASSERT_TRUE(v) << v.error();
  const Options p = Options::from(d, *v);
  EXPECT_FALSE(p.lowercase_incremental);
  EXPECT_TRUE(p.typographic_dash_is_error);
  EXPECT_TRUE(p.motion_cancels_cycle);
  EXPECT_FALSE(p.comp_radius_from_register);
}

}  // namespace
}  // namespace usina::gcode::romi
