// Issue 11: the elliptical pocket's parameters within their ranges, its
// moves estimated and bounded before any is made. (ellipse_pocket.hpp and
// offset.hpp both name a Ring: the ellipse has a test file of its own.)
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cam/ellipse_pocket.hpp"
#include "cam_test_util.hpp"
#include "canon/toolpath.hpp"

namespace usina::cam {
namespace {

using testing::count_code;

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

class CountingSink final : public canon::Sink {
 public:
  void on(const canon::Op&) override { ++ops; }

  double ops = 0;
};

std::string first_message(const core::DiagnosticList& d) {
  return d.all().empty() ? std::string() : d.all().front().message;
}

EllipsePocket ellipse() {
  EllipsePocket p;
  p.rx = 30;
  p.ry = 20;
  p.depth = 5;
  p.ae = 3;
  p.ap = 2;
  p.cut.tool_diameter = 8;
  return p;
}

// seed 002 with --resolution 1e-12 aborted in std::bad_alloc; 1e-20 cut a slot.
TEST(EllipseLimits, ResolutionBelowATenthOfAMicrometreIsAnError) {
  for (const double res : {1e-12, 1e-20, 1e-6, 0.0, -0.1, kNan}) {
    EllipsePocket p = ellipse();
    p.resolution = res;
    core::DiagnosticList d;
    canon::Toolpath tp;
    EXPECT_FALSE(generate_ellipse_pocket(p, tp, d)) << res;
    EXPECT_THAT(first_message(d), ::testing::HasSubstr("the resolution (--resolution)")) << res;
    EXPECT_TRUE(tp.ops().empty());
  }
}

TEST(EllipseLimits, TheEstimateIsNeverBelowTheMovesMade) {
  for (const double res : {1.0, 0.1, 0.01}) {
    for (const double rx : {30.0, 12.0}) {
      EllipsePocket p = ellipse();
      p.rx = rx;
      p.resolution = res;
      p.ap_finish = 0.5;
      core::DiagnosticList d;
      ASSERT_TRUE(check(p, d)) << first_message(d);
      CountingSink sink;
      generate(p, sink);
      EXPECT_GE(estimate_moves(p), sink.ops) << res << " " << rx;
      EXPECT_LE(estimate_moves(p), 1.5 * sink.ops) << res << " " << rx;  // and not far above
    }
  }
}

TEST(EllipseLimits, MoreMovesThanTheLimitIsRefusedBeforeAnyIsMade) {
  EllipsePocket p = ellipse();
  p.resolution = 0.0001;  // about 40 million moves
  core::DiagnosticList d;
  canon::Toolpath tp;
  EXPECT_FALSE(generate_ellipse_pocket(p, tp, d));
  EXPECT_EQ(count_code(d, core::Code::GenTooMuchWork), 1);
  EXPECT_THAT(first_message(d), ::testing::HasSubstr("more than the limit of 20,000,000"));
  EXPECT_TRUE(tp.ops().empty());
  p.resolution = 0.1;
  p.cut.max_moves = 100;  // the limit is the user's
  d.clear();
  EXPECT_FALSE(check(p, d));
  EXPECT_EQ(count_code(d, core::Code::GenTooMuchWork), 1);
}

TEST(EllipseLimits, ATinyStepoverOrStepDownIsAnErrorNotAHang) {
  for (const auto& change : std::vector<std::function<void(EllipsePocket&)>>{
           [](EllipsePocket& p) { p.ae = 1e-300; }, [](EllipsePocket& p) { p.ap = 1e-300; },
           [](EllipsePocket& p) { p.ae = 1e-4; }, [](EllipsePocket& p) { p.ap = 1e-4; }}) {
    EllipsePocket p = ellipse();
    change(p);
    core::DiagnosticList d;
    EXPECT_FALSE(check(p, d));
    EXPECT_TRUE(d.has_errors());
  }
}

}  // namespace
}  // namespace usina::cam
