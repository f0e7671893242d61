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
  OptionValues v;
  EXPECT_FALSE(resolve_options(*find_dialect("romi"), {}, v));
  EXPECT_EQ(v.at("lowercase_incremental"), "on");
  EXPECT_EQ(v.at("typographic_dash"), "minus");
  EXPECT_FALSE(resolve_options(*find_dialect("romi"), {"lowercase_incremental=off"}, v));
  EXPECT_EQ(v.at("lowercase_incremental"), "off");
}

TEST(Dialect, BadOptionsSayWhatIsValid) {
  OptionValues v;
  const Dialect& romi = *find_dialect("romi");
  auto unknown = resolve_options(romi, {"colour=red"}, v);
  ASSERT_TRUE(unknown);
  EXPECT_NE(unknown->find("comp_radius=register|tool"), std::string::npos) << *unknown;
  auto value = resolve_options(romi, {"comp_radius=both"}, v);
  ASSERT_TRUE(value);
  EXPECT_NE(value->find("register|tool"), std::string::npos) << *value;
  EXPECT_TRUE(resolve_options(romi, {"comp_radius"}, v));
  auto none = resolve_options(*find_dialect("rs274ngc"), {"x=y"}, v);
  ASSERT_TRUE(none);
  EXPECT_NE(none->find("has no options"), std::string::npos);
}

}  // namespace
}  // namespace usina::gcode
