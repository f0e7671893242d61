// L with G74 is a dialect's rule (DialectRules::g74_takes_l): LinuxCNC's
// check_other_codes leaves G74 out of the codes that take L, so its
// interpreter refuses "G74 ... L2" (the differential fuzzer found it against
// Debian's rs274); the fanuc front end hands its K repeats on as L, and the
// fanuc dialect repeats the hole.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "support/dialect_run.hpp"

namespace usina::gcode {
namespace {

using dialect_test::run_in;

constexpr const char* kG74WithL =
    "G21 G90 F100\nM4 S500\nG0 X0 Y0 Z5\nG91 G74 X1 Z-5 R1 L2\nG80\nM2\n";

TEST(G74Repeats, LinuxcncRefusesLWithG74) {
  auto r = run_in("rs274ngc", kG74WithL);
  EXPECT_FALSE(r->ok);
  EXPECT_EQ(r->first_error(), core::Code::UnusedWord);
  EXPECT_NE(r->first_error_text().find("L word with G74"), std::string::npos)
      << r->first_error_text();
}

TEST(G74Repeats, LinuxcncTakesLWithTheOtherCycles) {
  auto r = run_in("rs274ngc", "G21 G90 F100\nG0 X0 Y0 Z5\nG91 G81 X1 Z-5 R1 L2\nG80\nM2\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
}

TEST(G74Repeats, FanucRepeatsG74ByK) {
  auto r =
      run_in("fanuc",
             "O1\nG21 G90 F100.\nM4 S500\nG0 X0 Y0 Z5.\nG91 G98 G74 X1. Z-5. R-4. K2\nG80\nM30\n");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  // Two holes, X1 and X2 (G91: each X1 from the last), each fed in and out.
  std::vector<double> hole_x;
  for (const auto& f : r->all<canon::Feed>())
    if (hole_x.empty() || std::abs(hole_x.back() - f.to.x) > 1e-9) hole_x.push_back(f.to.x);
  EXPECT_EQ(hole_x, (std::vector<double>{1.0, 2.0}));
}

}  // namespace
}  // namespace usina::gcode
