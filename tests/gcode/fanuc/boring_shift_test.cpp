// The fanuc dialect's G76/G87 shift direction (docs/fanuc.md §7): the
// `boring_shift` option and parameter 5101 RD1 RD2 (G10 L50), the shift
// not turned by G68 or G51.1, and G76 outside G17. Each expected point is
// worked out by hand in the comment beside it.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "fanuc_test_support.hpp"

namespace usina::gcode::fanuc_test {
namespace {

using core::Code;
using core::Vec3;

// G76 at (5, 5) from the initial level 10, R 2, bottom -8, Q 0.5. The
// moves: [0] to the start, [1] over the hole, [2] R, [3] bottom, [4] the
// shift, [5] up to the initial level, [6] back over the hole.
const char* const kBore = "G0 X0 Y0 Z10.\nS500 M3\nG98 G76 X5. Y5. Z-8. R2. Q0.5 F60.\nG80\nM30\n";

Vec3 shift_of(const Run& r) {
  const auto ends = r.ends();
  EXPECT_GE(ends.size(), 7u);
  return ends.size() > 4 ? ends[4] : Vec3{};
}

TEST(FanucBoringShift, TheOptionSetsTheDirection) {
  const struct {
    const char* option;
    Vec3 shifted;
  } cases[] = {{"boring_shift=+x", {5.5, 5, -8}},
               {"boring_shift=-x", {4.5, 5, -8}},
               {"boring_shift=+y", {5, 5.5, -8}},
               {"boring_shift=-y", {5, 4.5, -8}}};

  for (const auto& c : cases) {
    SCOPED_TRACE(c.option);
    auto r = run_fanuc(kBore, {}, {c.option});
    ASSERT_TRUE(r->ok) << r->first_error_text();
    expect_near(shift_of(*r), c.shifted);
    expect_near(r->ends()[6], {5, 5, 10});  // shifted back at the initial level
  }
}

TEST(FanucBoringShift, DefaultIsPlusX) {
  auto r = run_fanuc(kBore);
  ASSERT_TRUE(r->ok) << r->first_error_text();
  expect_near(shift_of(*r), {5.5, 5, -8});
}

TEST(FanucBoringShift, AnUnknownDirectionIsRefused) {
  const Dialect* d = find_dialect("fanuc");
  ASSERT_NE(d, nullptr);
  EXPECT_FALSE(resolve_options(*d, {"boring_shift=+z"}).has_value());
}

TEST(FanucBoringShift, G87ShiftsInAndOutTheSameWay) {
  // -Y: in at (5, 4.5) before going down, out at (5, 4.5) at the top.
  auto r = run_fanuc("G0 X0 Y0 Z10.\nS500 M3\nG98 G87 X5. Y5. Z-2. R-20. Q0.5 F60.\nG80\nM30\n", {},
                     {"boring_shift=-y"});
  ASSERT_TRUE(r->ok) << r->first_error_text();
  const auto ends = r->ends();
  ASSERT_GE(ends.size(), 9u);
  expect_near(ends[2], {5, 4.5, 10});   // shifted in
  expect_near(ends[3], {5, 4.5, -20});  // down to the bottom
  expect_near(ends[4], {5, 5, -20});    // back on the hole's axis
  expect_near(ends[7], {5, 4.5, 10});   // out at the initial level
}

// Parameter 5101: bit 4 RD1, bit 5 RD2; R is the byte.
TEST(FanucBoringShift, G10L50Sets5101) {
  const struct {
    const char* value;
    Vec3 shifted;
  } cases[] = {{"R0", {5.5, 5, -8}},    // 00: +X
               {"R16", {4.5, 5, -8}},   // RD1: -X
               {"R32", {5, 5.5, -8}},   // RD2: +Y
               {"R48", {5, 4.5, -8}}};  // both: -Y

  for (const auto& c : cases) {
    SCOPED_TRACE(c.value);
    auto r = run_fanuc(std::string("G10 L50\nN5101 ") + c.value + "\nG11\n" + kBore, {},
                       {"boring_shift=-y"});
    ASSERT_TRUE(r->ok) << r->first_error_text();
    EXPECT_FALSE(r->has(Code::ParameterNotModeled));
    expect_near(shift_of(*r), c.shifted);
  }
}

TEST(FanucBoringShift, Other5101BitsAreWarned) {
  // R17: bit 0 (not modelled) and RD1 (-X).
  auto r = run_fanuc(std::string("G10 L50\nN5101 R17\nG11\n") + kBore);
  ASSERT_TRUE(r->ok) << r->first_error_text();
  EXPECT_TRUE(r->has(Code::ParameterNotModeled));
  expect_near(shift_of(*r), {4.5, 5, -8});
}

TEST(FanucBoringShift, A5101ValueWithAPointIsAnError) {
  auto r = run_fanuc("G10 L50\nN5101 R16.\nG11\nM30\n");
  EXPECT_EQ(r->first_error(), Code::BadWordValue);
  auto p = run_fanuc("G10 L50\nN5101 P1 R16\nG11\nM30\n");
  EXPECT_EQ(p->first_error(), Code::BadWordValue);
}

TEST(FanucBoringShift, RotationDoesNotTurnTheShift) {
  // G68 R90 about 0: the hole (5, 0) is bored at (0, 5); the oriented
  // spindle's tip still points +X, so the shift goes to (0.5, 5).
  auto r =
      run_fanuc("G0 X0 Y0 Z10.\nG68 X0 Y0 R90.\nG98 G76 X5. Y0 Z-8. R2. Q0.5 F60.\nG80\nM30\n");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  expect_near(r->ends()[3], {0, 5, -8});
  expect_near(shift_of(*r), {0.5, 5, -8});
}

TEST(FanucBoringShift, MirrorDoesNotReverseTheShift) {
  // G51.1 X0: the hole (5, 5) is bored at (-5, 5); the shift stays +X.
  auto r = run_fanuc("G0 X0 Y0 Z10.\nG51.1 X0\nG98 G76 X5. Y5. Z-8. R2. Q0.5 F60.\nG80\nM30\n");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  expect_near(r->ends()[3], {-5, 5, -8});
  expect_near(shift_of(*r), {-4.5, 5, -8});
}

TEST(FanucBoringShift, ScalingDoesNotScaleTheShift) {
  // G51 P2 about 0 (X Y only): the hole (5, 5) is bored at (10, 10); Q stays 0.5.
  auto r =
      run_fanuc("G0 X0 Y0 Z10.\nG51 X0 Y0 P2.\nG98 G76 X5. Y5. Z-8. R2. Q0.5 F60.\nG80\nM30\n");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  expect_near(r->ends()[3], {10, 10, -8});
  expect_near(shift_of(*r), {10.5, 10, -8});
}

TEST(FanucBoringShift, OutsideG17IsNotImplemented) {
  auto r = run_fanuc("G0 X0 Y0 Z10.\nG18 G98 G76 X5. Y5. Z-8. R2. Q0.5 F60.\nM30\n");
  EXPECT_EQ(r->first_error(), Code::Unsupported);
}

}  // namespace
}  // namespace usina::gcode::fanuc_test
