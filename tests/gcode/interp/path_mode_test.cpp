// G61, G61.1, G64 P Q reach the back ends as path_mode ops (LinuxCNC's
// SET_MOTION_CONTROL_MODE and SET_NAIVECAM_TOLERANCE): stats times corners by them.
#include <gtest/gtest.h>

#include "support/interp_run.hpp"

namespace usina::gcode::interp_test {
namespace {

using Mode = canon::PathMode::Mode;

TEST(PathMode, EachPathControlCodeIsAnOpWithItsTolerancesInMm) {
  const auto r = run("G61\nG61.1\nG64\nG64 P0.01\nG64 P0.02 Q0.5\nG20 G64 P0.001\nM2\n");
  ASSERT_TRUE(r->ok);
  const auto modes = r->all<canon::PathMode>();
  ASSERT_EQ(modes.size(), 6u);
  EXPECT_EQ(modes[0].mode, Mode::ExactPath);
  EXPECT_EQ(modes[1].mode, Mode::ExactStop);
  EXPECT_EQ(modes[2].mode, Mode::Blend);
  EXPECT_EQ(modes[2].tolerance, 0.0);  // no P: as fast as the corners allow
  EXPECT_EQ(modes[2].naive_cam, 0.0);
  EXPECT_DOUBLE_EQ(modes[3].tolerance, 0.01);
  EXPECT_DOUBLE_EQ(modes[3].naive_cam, 0.01);  // Q is P when absent
  EXPECT_DOUBLE_EQ(modes[4].tolerance, 0.02);
  EXPECT_DOUBLE_EQ(modes[4].naive_cam, 0.5);
  EXPECT_NEAR(modes[5].tolerance, 0.0254, 1e-12);  // inches to mm
}

TEST(PathMode, ANegativeToleranceIsAnError) {
  const auto r = run("G64 P-0.1\nM2\n");
  EXPECT_FALSE(r->ok);
  expect_error(*r, Code::NumberOutOfRange, 1, 5);
  EXPECT_TRUE(r->all<canon::PathMode>().empty());
}

}  // namespace
}  // namespace usina::gcode::interp_test
