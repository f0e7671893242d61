// canon/limits.hpp: the range of every number a canon op carries.
#include "canon/limits.hpp"

#include <limits>

#include <gtest/gtest.h>

namespace usina::canon {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(CanonLimits, OpsInRangePass) {
  EXPECT_EQ(out_of_range(Traverse{{1e9, -1e9, 0}, {1e9, 0, 0}}), std::nullopt);
  EXPECT_EQ(out_of_range(Feed{{1, 2, 3}, kMinFeed, {}, {}}), std::nullopt);
  EXPECT_EQ(out_of_range(Feed{{1, 2, 3}, std::nullopt, {}, {}}), std::nullopt);
  EXPECT_EQ(out_of_range(Arc{{1, 0, 0}, {0, 0, 0}, {0, 0, 1}, -kMaxTurns, 100.0, {}, {}}),
            std::nullopt);
  EXPECT_EQ(out_of_range(Dwell{kMaxDwell}), std::nullopt);
  EXPECT_EQ(out_of_range(Spindle{0.0, SpindleDir::Off}), std::nullopt);
  EXPECT_EQ(out_of_range(Comment{"nan"}), std::nullopt);
  EXPECT_EQ(out_of_range(ProgramEnd{}), std::nullopt);
}

TEST(CanonLimits, NonFiniteNumbersAreNamed) {
  const auto arc = out_of_range(Arc{{1, 0, 0}, {kNan, -kInf, 0}, {0, 0, 1}, -1, 100.0, {}, {}});
  ASSERT_TRUE(arc.has_value());
  EXPECT_EQ(*arc, "the arc's centre X (nan) is not a finite number");
  const auto t = out_of_range(Traverse{{kInf, 0, 0}, {}});
  ASSERT_TRUE(t.has_value());
  EXPECT_NE(t->find("end X (inf)"), std::string::npos) << *t;
  EXPECT_TRUE(out_of_range(Spline{{0, 0, 0}, {{0, kNan, 0}}, 100.0, {}}).has_value());
  EXPECT_TRUE(out_of_range(Probe{{0, 0, 0}, {0, kNan, 0}}).has_value());
}

TEST(CanonLimits, BeyondTheBoundsIsOutOfRange) {
  const auto t = out_of_range(Traverse{{2e9, 0, 0}, {}});
  ASSERT_TRUE(t.has_value());
  EXPECT_EQ(*t, "the traverse's end X 2e+09 mm is beyond ±1e9 mm");
  EXPECT_TRUE(out_of_range(Traverse{{0, 0, 0}, {0, 0, 2e9}}).has_value());  // C in degrees
  EXPECT_TRUE(out_of_range(Feed{{0, 0, 0}, 2e9, {}, {}}).has_value());
  EXPECT_TRUE(out_of_range(Feed{{0, 0, 0}, 1e-9, {}, {}}).has_value());  // below kMinFeed
  EXPECT_TRUE(out_of_range(Feed{{0, 0, 0}, -1.0, {}, {}}).has_value());
  EXPECT_TRUE(
      out_of_range(Feed{{0, 0, 0}, std::nullopt, {}, {ProgrammedFeed::Mode::InverseTime, 1e-300}})
          .has_value());
  EXPECT_TRUE(out_of_range(Dwell{-1.0}).has_value());
  EXPECT_TRUE(out_of_range(Dwell{2e9}).has_value());
  EXPECT_TRUE(out_of_range(Spindle{2e9, SpindleDir::Cw}).has_value());
  EXPECT_TRUE(out_of_range(ToolChange{1, 2e9}).has_value());
  EXPECT_TRUE(out_of_range(Hole{{0, 0, 0}, 6.0, kInf}).has_value());
  EXPECT_TRUE(out_of_range(Arc{{1, 0, 0}, {0, 0, 0}, {0, 0, 1}, 0, 100.0, {}, {}}).has_value());
  EXPECT_TRUE(
      out_of_range(Arc{{1, 0, 0}, {0, 0, 0}, {0, 0, 1}, kMaxTurns + 1, 100.0, {}, {}}).has_value());
  Outline o;
  o.segs.push_back({{1, 0}, Vec2{kNan, 0}, 1});
  EXPECT_TRUE(out_of_range(Pocket{o, 1.0}).has_value());
}

TEST(CanonLimits, SingleValues) {
  EXPECT_EQ(length_out_of_range("X", 1e9), std::nullopt);
  EXPECT_EQ(*length_out_of_range("X", -1.5e9), "X -1.5e+09 mm is beyond ±1e9 mm");
  EXPECT_TRUE(length_out_of_range("X", kNan).has_value());
  EXPECT_EQ(feed_out_of_range("F", 0.0), std::nullopt);
  EXPECT_TRUE(feed_out_of_range("F", 1e-7).has_value());
  EXPECT_EQ(limit_text(1e9), "1e9");
  EXPECT_EQ(limit_text(1e-6), "1e-6");
}

}  // namespace
}  // namespace usina::canon
