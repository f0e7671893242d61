// The dialect registry, the dialects' tables and the option settings.
#include "gcode/dialect.hpp"

#include <gtest/gtest.h>

#include "gcode/romi/engine.hpp"

namespace usina::gcode {
namespace {

TEST(Dialect, RegistryKnowsEveryDialect) {
  ASSERT_NE(find_dialect("rs274ngc"), nullptr);
  ASSERT_NE(find_dialect("romi"), nullptr);
  ASSERT_NE(find_dialect("fanuc"), nullptr);
  ASSERT_NE(find_dialect("grbl"), nullptr);
  EXPECT_EQ(find_dialect("no-such-control"), nullptr);
  EXPECT_EQ(all_dialects().size(), 4u);
  for (const Dialect* d : all_dialects())
    EXPECT_NE(d->make_runner, nullptr) << d->name;
}

TEST(Dialect, EveryRomiCodeHasAHandlerAndOneEntry) {
  const Dialect& d = *find_dialect("romi");
  for (const CodeEntry& e : d.codes) {
    EXPECT_TRUE(romi::Engine::knows_handler(e.handler)) << e.letter << e.code << " " << e.handler;
    EXPECT_EQ(d.find_code(e.letter, e.code), &e) << e.letter << e.code;
  }
  for (const CodeEntry& e : d.start_codes) {
    const CodeEntry* table = d.find_code(e.letter, e.code);
    ASSERT_NE(table, nullptr) << e.letter << e.code;
    EXPECT_EQ(table->group, e.group);
    EXPECT_EQ(table->handler, e.handler);
  }
  EXPECT_EQ(d.find_code('G', 180), nullptr);
}

TEST(Dialect, OptionsDefaultToTheFirstValue) {
  const auto v = resolve_options(*find_dialect("romi"), {});
  ASSERT_TRUE(v) << v.error();
  EXPECT_EQ(v->at("lowercase_incremental"), "on");
  EXPECT_EQ(v->at("typographic_dash"), "minus");
  EXPECT_EQ(*v, default_options(*find_dialect("romi")));
  const auto off = resolve_options(*find_dialect("romi"), {"lowercase_incremental=off"});
  ASSERT_TRUE(off) << off.error();
  EXPECT_EQ(off->at("lowercase_incremental"), "off");
  EXPECT_EQ(off->at("typographic_dash"), "minus");
}

TEST(Dialect, BadOptionsSayWhatIsValid) {
  const Dialect& romi = *find_dialect("romi");
  auto unknown = resolve_options(romi, {"colour=red"});
  ASSERT_FALSE(unknown);
  EXPECT_NE(unknown.error().find("comp_radius=register|tool"), std::string::npos)
      << unknown.error();
  auto value = resolve_options(romi, {"comp_radius=both"});
  ASSERT_FALSE(value);
  EXPECT_NE(value.error().find("register|tool"), std::string::npos) << value.error();
  EXPECT_FALSE(resolve_options(romi, {"comp_radius"}));
  auto none = resolve_options(*find_dialect("rs274ngc"), {"x=y"});
  ASSERT_FALSE(none);
  EXPECT_NE(none.error().find("has no options"), std::string::npos);
}

}  // namespace
}  // namespace usina::gcode
