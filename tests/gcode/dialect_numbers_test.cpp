// Every dialect reads a number the same way (gcode/decimal.hpp): the same
// digits give the same double, correctly rounded, so a program converted
// from one dialect to another keeps its points to the last bit.
#include <string>

#include <gtest/gtest.h>

#include "support/dialect_run.hpp"

namespace usina::gcode {
namespace {

using core::Vec3;

// One feed move to (0.75, 1.4833, -0.7487) and one to a 20-digit X.
const Vec3 kFirst{0.75, 1.4833, -0.7487};
const double kLongX = 1.2345678901234567;  // 1.23456789012345678901 correctly rounded

void expect_points(const std::string& dialect, const std::string& program) {
  auto r = dialect_test::run_in(dialect.c_str(), program, {}, {});
  ASSERT_TRUE(r->ok) << dialect << ": " << r->first_error_text();
  ASSERT_GE(r->ends().size(), 2u) << dialect;
  EXPECT_EQ(r->ends()[0], kFirst) << dialect;
  EXPECT_EQ(r->ends()[1].x, kLongX) << dialect;
}

TEST(DialectNumbers, EveryDialectReadsTheSameDigitsAsTheSameDouble) {
  const std::string moves = "G1 X0.75 Y1.4833 Z-0.7487 F1500.\nG1 X1.23456789012345678901\n";
  expect_points("rs274ngc", moves + "M2\n");
  expect_points("fanuc", moves + "M30\n");
  expect_points("grbl", moves + "M2\n");
  expect_points("romi", "G01 X0.75 Y1.4833 Z-0.7487 F1500\nX1.23456789012345678901\nM30\n");
}

}  // namespace
}  // namespace usina::gcode
