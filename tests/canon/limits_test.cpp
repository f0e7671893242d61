// canon/limits.hpp: the range of every number a canon op carries.
#include "canon/limits.hpp"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

namespace usina::canon {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(CanonLimits, OpsInRangePass) {
  EXPECT_TRUE(check_range(Traverse{{1e9, -1e9, 0}, {1e9, 0, 0}}));
  EXPECT_TRUE(check_range(Feed{{1, 2, 3}, kMinFeed, {}, {}}));
  EXPECT_TRUE(check_range(Feed{{1, 2, 3}, std::nullopt, {}, {}}));
  EXPECT_TRUE(check_range(Arc{{1, 0, 0}, {0, 0, 0}, {0, 0, 1}, -kMaxTurns, 100.0, {}, {}}));
  EXPECT_TRUE(check_range(Dwell{kMaxDwell}));
  EXPECT_TRUE(check_range(Spindle{0.0, SpindleDir::Off}));
  EXPECT_TRUE(check_range(Comment{"nan"}));
  EXPECT_TRUE(check_range(ProgramEnd{}));
}

TEST(CanonLimits, NonFiniteNumbersAreNamed) {
  const auto arc = check_range(Arc{{1, 0, 0}, {kNan, -kInf, 0}, {0, 0, 1}, -1, 100.0, {}, {}});
  ASSERT_FALSE(arc);
  EXPECT_EQ(arc.error(), "the arc's centre X (nan) is not a finite number");
  const auto t = check_range(Traverse{{kInf, 0, 0}, {}});
  ASSERT_FALSE(t);
  EXPECT_NE(t.error().find("end X (inf)"), std::string::npos) << t.error();
  EXPECT_FALSE(check_range(Spline{{0, 0, 0}, {{0, kNan, 0}}, 100.0, {}}));
  EXPECT_FALSE(check_range(Probe{{0, 0, 0}, {0, kNan, 0}}));
}

TEST(CanonLimits, BeyondTheBoundsIsOutOfRange) {
  const auto t = check_range(Traverse{{2e9, 0, 0}, {}});
  ASSERT_FALSE(t);
  EXPECT_EQ(t.error(), "the traverse's end X 2e+09 mm is beyond ±1e9 mm");
  EXPECT_FALSE(check_range(Traverse{{0, 0, 0}, {0, 0, 2e9}}));  // C in degrees
  EXPECT_FALSE(check_range(Feed{{0, 0, 0}, 2e9, {}, {}}));
  EXPECT_FALSE(check_range(Feed{{0, 0, 0}, 1e-9, {}, {}}));  // below kMinFeed
  EXPECT_FALSE(check_range(Feed{{0, 0, 0}, -1.0, {}, {}}));
  EXPECT_FALSE(
      check_range(Feed{{0, 0, 0}, std::nullopt, {}, {ProgrammedFeed::Mode::InverseTime, 1e-300}}));
  EXPECT_FALSE(check_range(Dwell{-1.0}));
  EXPECT_FALSE(check_range(Dwell{2e9}));
  EXPECT_FALSE(check_range(Spindle{2e9, SpindleDir::Cw}));
  EXPECT_FALSE(check_range(ToolChange{1, 2e9}));
  EXPECT_FALSE(check_range(Hole{{0, 0, 0}, 6.0, kInf}));
  EXPECT_FALSE(check_range(Arc{{1, 0, 0}, {0, 0, 0}, {0, 0, 1}, 0, 100.0, {}, {}}));
  EXPECT_FALSE(check_range(Arc{{1, 0, 0}, {0, 0, 0}, {0, 0, 1}, kMaxTurns + 1, 100.0, {}, {}}));
  Outline o;
  o.segs.push_back({{1, 0}, Vec2{kNan, 0}, 1});
  EXPECT_FALSE(check_range(Pocket{o, 1.0}));
}

// Moves are first checked without the checker that names the number (an
// inline shortcut for the usual move, plainly_in_range): each field of a
// traverse and a feed at and just past its bounds, as an op and as a move,
// with the verdict the bounds give and a message whenever it fails.
TEST(CanonLimits, MovesAtTheirBounds) {
  const double past = std::nextafter(1e9, kInf);
  const double below_min = std::nextafter(kMinFeed, 0.0);

  struct Case {
    double v;
    bool length_ok, rate_ok;
  };

  const Case cases[] = {{0.0, true, true},        {kMinFeed, true, true}, {below_min, true, false},
                        {-kMinFeed, true, false}, {1e9, true, true},      {-1e9, true, false},
                        {past, false, false},     {-past, false, false},  {kNan, false, false},
                        {kInf, false, false}};
  for (const Case& c : cases) {
    for (int field = 0; field < 6; ++field) {
      Feed f{{1, 2, 3}, 100.0, {}, {ProgrammedFeed::Mode::PerMinute, 100.0}};
      Traverse t{{1, 2, 3}, {}};
      bool ok = c.length_ok;
      switch (field) {
      case 0: f.to.x = t.to.x = c.v; break;
      case 1: f.to.z = t.to.z = c.v; break;
      case 2: f.abc[1] = t.abc[1] = c.v; break;
      case 3: f.f = c.v, ok = c.rate_ok; break;
      case 4: f.programmed.value = c.v, ok = c.rate_ok; break;
      default: f.f = std::nullopt, f.programmed.value = c.v, ok = c.rate_ok; break;
      }
      SCOPED_TRACE(testing::Message() << "value " << c.v << ", field " << field);
      const auto move = check_range(f);
      EXPECT_EQ(move.has_value(), ok);
      if (!move) {
        EXPECT_FALSE(move.error().empty());
      }
      EXPECT_EQ(check_range(OpKind{f}).has_value(), ok);
      // The inline shortcut and the checker agree, each on its own.
      EXPECT_EQ(plainly_in_range(f), ok);
      EXPECT_EQ(range_problem(f).has_value(), ok);
      EXPECT_EQ(range_problem(OpKind{f}).has_value(), ok);
      if (field <= 2) {
        EXPECT_EQ(check_range(t).has_value(), c.length_ok);
        EXPECT_EQ(check_range(OpKind{t}).has_value(), c.length_ok);
        EXPECT_EQ(plainly_in_range(t), c.length_ok);
        EXPECT_EQ(range_problem(t).has_value(), c.length_ok);
      }
    }
  }
}

TEST(CanonLimits, SingleValues) {
  EXPECT_TRUE(check_length("X", 1e9));
  EXPECT_EQ(check_length("X", -1.5e9).error(), "X -1.5e+09 mm is beyond ±1e9 mm");
  EXPECT_FALSE(check_length("X", kNan));
  EXPECT_TRUE(check_feed("F", 0.0));
  EXPECT_FALSE(check_feed("F", 1e-7));
  EXPECT_EQ(limit_text(1e9), "1e9");
  EXPECT_EQ(limit_text(1e-6), "1e-6");
}

}  // namespace
}  // namespace usina::canon
