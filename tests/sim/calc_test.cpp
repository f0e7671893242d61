// The calculators of seed 004: its examples 7.1-7.3 as printed, the cutting
// equations 7.1/7.2, table 7.4, and every input the formulas refuse.
#include "sim/calc.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

namespace usina::sim {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// The seed's figures are printed to three decimals (333,333 Hz).
constexpr double kPrinted = 0.0005;

bool mentions(const std::string& message, const std::string& part) {
  return message.find(part) != std::string::npos;
}

// Example 7.1: p = 6 mm, r_g = 5, n_s = 48, x = 250 mm, f_r = 500 mm/min.
OpenLoopInput example_7_1() {
  return {{6.0, 5.0}, 48, 250.0, 500.0};
}

// Example 7.2: the same drive with a 48-slot encoder on the screw.
ClosedLoopInput example_7_2() {
  return {{6.0, 5.0}, 48, 250.0, 500.0};
}

// Example 7.3: example 7.1's axis, L = 1000 mm, B = 16 bits, sigma = 0.005 mm.
PrecisionInput example_7_3() {
  return {{6.0, 5.0}, 48, 1000.0, 16, 0.005};
}

// --- open loop (7.5.1) --------------------------------------------------------

TEST(CalcOpenLoop, Example71ReproducesThePrintedAnswers) {
  const auto r = open_loop(example_7_1());
  ASSERT_TRUE(r.has_value()) << r.error();
  EXPECT_DOUBLE_EQ(r->screw_angle_deg, 15000.0);  // A = 15.000 deg
  EXPECT_DOUBLE_EQ(r->step_angle_deg, 7.5);       // alpha = 7,5
  EXPECT_DOUBLE_EQ(r->pulses, 10000.0);           // 10.000 pulsos
  EXPECT_EQ(r->whole_pulses, 10000);
  EXPECT_DOUBLE_EQ(r->distance_reached_mm, 250.0);
  EXPECT_NEAR(r->screw_rpm, 83.333, kPrinted);            // 83,333 rev/min
  EXPECT_NEAR(r->motor_rpm, 416.667, kPrinted);           // 416,667 rev/min
  EXPECT_NEAR(r->pulse_frequency_hz, 333.333, kPrinted);  // 333,333 Hz
  EXPECT_DOUBLE_EQ(r->pulse_frequency_hz, 1000.0 / 3.0);
  EXPECT_DOUBLE_EQ(r->motor_angle_deg, 75000.0);
}

TEST(CalcOpenLoop, PulseFrequencyAgreesWithScrewSpeed) {
  // (7.9) read back: N = 60 f_p / (n_s r_g) must give (7.10)'s N.
  const auto r = open_loop(example_7_1());
  ASSERT_TRUE(r.has_value());
  EXPECT_DOUBLE_EQ(60.0 * r->pulse_frequency_hz / (48.0 * 5.0), r->screw_rpm);
}

TEST(CalcOpenLoop, AFractionOfAStepRoundsToTheNearestWholeStep) {
  OpenLoopInput in = example_7_1();
  in.distance_mm = 250.01;  // 10000.4 steps; CR = 0.025 mm
  const auto r = open_loop(in);
  ASSERT_TRUE(r.has_value());
  EXPECT_NEAR(r->pulses, 10000.4, 1e-9);
  EXPECT_EQ(r->whole_pulses, 10000);
  EXPECT_DOUBLE_EQ(r->distance_reached_mm, 250.0);
}

TEST(CalcOpenLoop, NegativeDistanceCountsPulsesTheOtherWay) {
  OpenLoopInput in = example_7_1();
  in.distance_mm = -250.0;
  const auto r = open_loop(in);
  ASSERT_TRUE(r.has_value());
  EXPECT_DOUBLE_EQ(r->pulses, -10000.0);
  EXPECT_EQ(r->whole_pulses, -10000);
  EXPECT_DOUBLE_EQ(r->distance_reached_mm, -250.0);
  EXPECT_GT(r->pulse_frequency_hz, 0.0);  // the speed has no sign
}

TEST(CalcOpenLoop, ZeroDistanceNeedsNoPulses) {
  OpenLoopInput in = example_7_1();
  in.distance_mm = 0.0;
  const auto r = open_loop(in);
  ASSERT_TRUE(r.has_value());
  EXPECT_EQ(r->pulses, 0.0);
  EXPECT_EQ(r->whole_pulses, 0);
}

TEST(CalcOpenLoop, DirectDriveHasEqualScrewAndMotorSpeeds) {
  OpenLoopInput in = example_7_1();
  in.drive.gear_ratio = 1.0;
  const auto r = open_loop(in);
  ASSERT_TRUE(r.has_value());
  EXPECT_DOUBLE_EQ(r->screw_rpm, r->motor_rpm);
  EXPECT_DOUBLE_EQ(r->pulses, 2000.0);
}

TEST(CalcOpenLoop, RejectsZeroOrNegativePitchRatioStepsAndFeed) {
  for (const double bad : {0.0, -6.0, kNaN, kInf}) {
    OpenLoopInput in = example_7_1();
    in.drive.pitch_mm = bad;
    const auto r = open_loop(in);
    EXPECT_FALSE(r.has_value()) << bad;
    EXPECT_TRUE(mentions(r.error(), "pitch")) << r.error();
  }
  for (const double bad : {0.0, -5.0, kNaN}) {
    OpenLoopInput in = example_7_1();
    in.drive.gear_ratio = bad;
    EXPECT_TRUE(mentions(open_loop(in).error(), "gear ratio")) << bad;
  }
  for (const std::int64_t bad : {0, -48}) {
    OpenLoopInput in = example_7_1();
    in.steps_per_rev = bad;
    EXPECT_TRUE(mentions(open_loop(in).error(), "steps per revolution")) << bad;
  }
  for (const double bad : {0.0, -500.0, kInf}) {
    OpenLoopInput in = example_7_1();
    in.feed_mm_per_min = bad;
    EXPECT_TRUE(mentions(open_loop(in).error(), "feed")) << bad;
  }
}

TEST(CalcOpenLoop, ErrorSaysTheValueGiven) {
  OpenLoopInput in = example_7_1();
  in.drive.pitch_mm = -6.0;
  EXPECT_EQ(open_loop(in).error(),
            "the screw pitch p must be a number greater than 0 mm/rev, not -6");
}

TEST(CalcOpenLoop, RejectsANonFiniteDistance) {
  for (const double bad : {kNaN, kInf, -kInf}) {
    OpenLoopInput in = example_7_1();
    in.distance_mm = bad;
    EXPECT_TRUE(mentions(open_loop(in).error(), "distance")) << bad;
  }
}

TEST(CalcOpenLoop, OverflowIsAnErrorNotInfinity) {
  OpenLoopInput in = example_7_1();
  in.drive.pitch_mm = 1e-300;
  in.distance_mm = 1e300;
  const auto r = open_loop(in);
  EXPECT_FALSE(r.has_value());
  EXPECT_TRUE(mentions(r.error(), "overflow")) << r.error();
}

TEST(CalcOpenLoop, MoreThanTwoToThe53PulsesIsAnError) {
  OpenLoopInput in = example_7_1();
  in.distance_mm = 1e15;  // 4e16 pulses
  const auto r = open_loop(in);
  EXPECT_FALSE(r.has_value());
  EXPECT_TRUE(mentions(r.error(), "2^53")) << r.error();
}

// --- closed loop (7.5.2) ------------------------------------------------------

TEST(CalcClosedLoop, Example72ReproducesThePrintedAnswers) {
  const auto r = closed_loop(example_7_2());
  ASSERT_TRUE(r.has_value()) << r.error();
  EXPECT_DOUBLE_EQ(r->pulses, 2000.0);  // 2.000 pulsos
  EXPECT_EQ(r->whole_pulses, 2000);
  EXPECT_NEAR(r->pulse_frequency_hz, 66.667, kPrinted);  // 66,667 Hz
  EXPECT_DOUBLE_EQ(r->pulse_frequency_hz, 200.0 / 3.0);
  EXPECT_NEAR(r->motor_rpm, 416.667, kPrinted);  // 416,667 rev/min, as in 7.1
  EXPECT_DOUBLE_EQ(r->slot_angle_deg, 7.5);
  EXPECT_DOUBLE_EQ(r->screw_angle_deg, 15000.0);
}

TEST(CalcClosedLoop, PulsesAreScrewAngleOverSlotAngle) {
  // (7.13) and (7.14) count the same pulses.
  const auto r = closed_loop(example_7_2());
  ASSERT_TRUE(r.has_value());
  EXPECT_DOUBLE_EQ(r->screw_angle_deg / r->slot_angle_deg, r->pulses);
}

TEST(CalcClosedLoop, GearRatioChangesOnlyTheMotorSpeed) {
  ClosedLoopInput in = example_7_2();
  in.drive.gear_ratio = 10.0;
  const auto r = closed_loop(in);
  ASSERT_TRUE(r.has_value());
  EXPECT_DOUBLE_EQ(r->pulses, 2000.0);
  EXPECT_DOUBLE_EQ(r->pulse_frequency_hz, 200.0 / 3.0);
  EXPECT_NEAR(r->motor_rpm, 833.333, kPrinted);
}

TEST(CalcClosedLoop, FractionalCountRoundsAndSaysWhereTheTableStops) {
  ClosedLoopInput in = example_7_2();
  in.distance_mm = 250.1;  // 2000.8 pulses; one pulse is 0.125 mm
  const auto r = closed_loop(in);
  ASSERT_TRUE(r.has_value());
  EXPECT_EQ(r->whole_pulses, 2001);
  EXPECT_DOUBLE_EQ(r->distance_reached_mm, 250.125);
}

TEST(CalcClosedLoop, RejectsBadDriveSlotsAndFeed) {
  ClosedLoopInput in = example_7_2();
  in.encoder_slots = 0;
  EXPECT_TRUE(mentions(closed_loop(in).error(), "encoder slots"));
  in = example_7_2();
  in.drive.pitch_mm = 0.0;
  EXPECT_TRUE(mentions(closed_loop(in).error(), "pitch"));
  in = example_7_2();
  in.feed_mm_per_min = -1.0;
  EXPECT_TRUE(mentions(closed_loop(in).error(), "feed"));
  in = example_7_2();
  in.distance_mm = kNaN;
  EXPECT_TRUE(mentions(closed_loop(in).error(), "distance"));
}

TEST(CalcClosedLoop, OverflowIsAnError) {
  ClosedLoopInput in = example_7_2();
  in.drive.pitch_mm = 1e-300;
  in.feed_mm_per_min = 1e300;
  EXPECT_TRUE(mentions(closed_loop(in).error(), "overflow"));
}

// --- precision (7.5.3) --------------------------------------------------------

TEST(CalcPrecision, Example73ReproducesThePrintedAnswers) {
  const auto r = precision(example_7_3());
  ASSERT_TRUE(r.has_value()) << r.error();
  EXPECT_DOUBLE_EQ(r->cr1_mm, 0.025);         // 6 / (48 x 5)
  EXPECT_NEAR(r->cr2_mm, 0.01526, 0.000005);  // 1000 / 65.535
  EXPECT_DOUBLE_EQ(r->cr2_mm, 1000.0 / 65535.0);
  EXPECT_DOUBLE_EQ(r->control_resolution_mm, 0.025);
  EXPECT_FALSE(r->limited_by_register);
  EXPECT_NEAR(r->accuracy_mm, 0.0275, 1e-12);      // 0,5(0,025) + 3(0,005)
  EXPECT_NEAR(r->repeatability_mm, 0.015, 1e-12);  // +/- 3(0,005)
}

TEST(CalcPrecision, FewBitsMakeTheRegisterTheLimit) {
  PrecisionInput in = example_7_3();
  in.bits = 8;
  const auto r = precision(in);
  ASSERT_TRUE(r.has_value());
  EXPECT_DOUBLE_EQ(r->cr2_mm, 1000.0 / 255.0);
  EXPECT_DOUBLE_EQ(r->control_resolution_mm, r->cr2_mm);
  EXPECT_TRUE(r->limited_by_register);
  EXPECT_DOUBLE_EQ(r->accuracy_mm, r->cr2_mm / 2.0 + 0.015);
}

TEST(CalcPrecision, OneBitSplitsTheTravelIntoOneGap) {
  PrecisionInput in = example_7_3();
  in.bits = 1;
  const auto r = precision(in);
  ASSERT_TRUE(r.has_value());
  EXPECT_DOUBLE_EQ(r->cr2_mm, 1000.0);
}

TEST(CalcPrecision, SixtyFourBitsStayFinite) {
  PrecisionInput in = example_7_3();
  in.bits = 64;
  const auto r = precision(in);
  ASSERT_TRUE(r.has_value());
  EXPECT_TRUE(std::isfinite(r->cr2_mm));
  EXPECT_GT(r->cr2_mm, 0.0);
  EXPECT_LT(r->cr2_mm, 1e-15);
}

TEST(CalcPrecision, PerfectMechanicsLeaveHalfTheResolution) {
  PrecisionInput in = example_7_3();
  in.sigma_mm = 0.0;
  const auto r = precision(in);
  ASSERT_TRUE(r.has_value());
  EXPECT_DOUBLE_EQ(r->accuracy_mm, 0.0125);
  EXPECT_EQ(r->repeatability_mm, 0.0);
}

TEST(CalcPrecision, BitsOutsideOneToSixtyFourAreAnError) {
  for (const std::int64_t bad : {0, -1, 65, 1000}) {
    PrecisionInput in = example_7_3();
    in.bits = bad;
    const auto r = precision(in);
    EXPECT_FALSE(r.has_value()) << bad;
    EXPECT_TRUE(mentions(r.error(), "from 1 to 64")) << r.error();
  }
}

TEST(CalcPrecision, RejectsNegativeSigmaAndZeroTravel) {
  for (const double bad : {-0.005, kNaN, kInf}) {
    PrecisionInput in = example_7_3();
    in.sigma_mm = bad;
    EXPECT_TRUE(mentions(precision(in).error(), "standard deviation")) << bad;
  }
  PrecisionInput in = example_7_3();
  in.travel_mm = 0.0;
  EXPECT_TRUE(mentions(precision(in).error(), "travel"));
  in = example_7_3();
  in.steps_per_rev = 0;
  EXPECT_TRUE(mentions(precision(in).error(), "steps"));
  in = example_7_3();
  in.drive.gear_ratio = -5.0;
  EXPECT_TRUE(mentions(precision(in).error(), "gear ratio"));
}

// --- cutting (7.1, 7.2) -------------------------------------------------------

TEST(CalcCutting, SpindleSpeedFromCuttingSpeed) {
  // (7.1): 100 m/min on a 20 mm cutter.
  const auto r = cutting({100.0, 20.0, std::nullopt, std::nullopt});
  ASSERT_TRUE(r.has_value()) << r.error();
  EXPECT_DOUBLE_EQ(r->spindle_rpm, 100000.0 / (std::numbers::pi * 20.0));
  EXPECT_NEAR(r->spindle_rpm, 1591.55, 0.005);
  EXPECT_FALSE(r->feed_mm_per_min.has_value());
}

TEST(CalcCutting, FeedRateFromTeethAndChipLoad) {
  // (7.2): 4 teeth at 0.05 mm per tooth.
  const auto r = cutting({100.0, 20.0, 4, 0.05});
  ASSERT_TRUE(r.has_value()) << r.error();
  ASSERT_TRUE(r->feed_mm_per_min.has_value());
  EXPECT_DOUBLE_EQ(*r->feed_mm_per_min, r->spindle_rpm * 4 * 0.05);
  EXPECT_NEAR(*r->feed_mm_per_min, 318.31, 0.005);
}

TEST(CalcCutting, TeethAndChipLoadComeTogether) {
  EXPECT_TRUE(mentions(cutting({100.0, 20.0, 4, std::nullopt}).error(), "both"));
  EXPECT_TRUE(mentions(cutting({100.0, 20.0, std::nullopt, 0.05}).error(), "both"));
}

TEST(CalcCutting, RejectsZeroOrNegativeValues) {
  EXPECT_TRUE(mentions(cutting({0.0, 20.0, std::nullopt, std::nullopt}).error(), "speed"));
  EXPECT_TRUE(mentions(cutting({kNaN, 20.0, std::nullopt, std::nullopt}).error(), "speed"));
  EXPECT_TRUE(mentions(cutting({100.0, -20.0, std::nullopt, std::nullopt}).error(), "diameter"));
  EXPECT_TRUE(mentions(cutting({100.0, 20.0, 0, 0.05}).error(), "teeth"));
  EXPECT_TRUE(mentions(cutting({100.0, 20.0, 4, 0.0}).error(), "chip load"));
  EXPECT_TRUE(mentions(cutting({100.0, 20.0, 4, -0.05}).error(), "chip load"));
}

TEST(CalcCutting, OverflowIsAnError) {
  EXPECT_TRUE(mentions(cutting({1e308, 1e-300, std::nullopt, std::nullopt}).error(), "overflow"));
}

// --- BCD (table 7.4) ----------------------------------------------------------

TEST(CalcBcd, EveryDigitAsTable74) {
  const std::array<const char*, 10> table = {"0000", "0001", "0010", "0011", "0100",
                                             "0101", "0110", "0111", "1000", "1001"};
  for (int d = 0; d <= 9; ++d) {
    const auto r = bcd(std::to_string(d));
    ASSERT_TRUE(r.has_value()) << r.error();
    ASSERT_EQ(r->digits.size(), 1u);
    EXPECT_EQ(r->digits[0].bits, table.at(static_cast<std::size_t>(d))) << d;
    EXPECT_EQ(r->value, static_cast<std::uint64_t>(d));
  }
}

TEST(CalcBcd, The1250OfTheSeed) {
  const auto r = bcd("1250");
  ASSERT_TRUE(r.has_value()) << r.error();
  ASSERT_EQ(r->digits.size(), 4u);
  EXPECT_EQ(r->digits[0].bits, "0001");
  EXPECT_EQ(r->digits[0].place_value, 1000u);
  EXPECT_EQ(r->digits[1].bits, "0010");
  EXPECT_EQ(r->digits[1].place_value, 200u);
  EXPECT_EQ(r->digits[2].bits, "0101");
  EXPECT_EQ(r->digits[2].place_value, 50u);
  EXPECT_EQ(r->digits[3].bits, "0000");
  EXPECT_EQ(r->digits[3].place_value, 0u);
  EXPECT_EQ(r->value, 1250u);
  EXPECT_EQ(r->code, "0001 0010 0101 0000");
}

TEST(CalcBcd, LeadingZerosAreDigitsAsOnTape) {
  // X07000 of the seed's word-address example.
  const auto r = bcd("07000");
  ASSERT_TRUE(r.has_value());
  EXPECT_EQ(r->digits.size(), 5u);
  EXPECT_EQ(r->value, 7000u);
  EXPECT_EQ(r->code, "0000 0111 0000 0000 0000");
}

TEST(CalcBcd, NineteenDigitsFitTwentyDoNot) {
  const auto r = bcd("9999999999999999999");
  ASSERT_TRUE(r.has_value()) << r.error();
  EXPECT_EQ(r->value, 9999999999999999999u);
  EXPECT_EQ(r->digits[0].place_value, 9000000000000000000u);
  EXPECT_TRUE(mentions(bcd("10000000000000000000").error(), "at most 19"));
}

TEST(CalcBcd, RejectsNegativeNonIntegerAndNonNumbers) {
  EXPECT_TRUE(mentions(bcd("-5").error(), "negative"));
  EXPECT_TRUE(mentions(bcd("12.5").error(), "not a whole number"));
  EXPECT_TRUE(mentions(bcd("1e3").error(), "not a whole number"));
  EXPECT_TRUE(mentions(bcd("+5").error(), "sign"));
  EXPECT_TRUE(mentions(bcd("abc").error(), "not a decimal number"));
  EXPECT_TRUE(mentions(bcd(" 5").error(), "not a decimal number"));
  EXPECT_TRUE(mentions(bcd("").error(), "give the number"));
}

}  // namespace
}  // namespace usina::sim
