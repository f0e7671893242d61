// The engineering figures of an NC positioning system and of a cutting
// operation: seed 004, section 7.5 (equations 7.3-7.20), the cutting
// equations 7.1 and 7.2 and table 7.4 (BCD). Pure functions; each returns the
// figures or the reason the inputs give none. Lengths in mm, speeds in mm/min,
// rotation in rev/min, pulse trains in Hz, angles in degrees.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <tl/expected.hpp>

namespace usina::sim {

// A calculator's answer: the figures, or a message saying which input is
// wrong, with its value, and what to give instead.
template <typename T>
using Checked = tl::expected<T, std::string>;

// The mechanics common to both loops: a lead screw of pitch p driven by a
// motor through a gear box of ratio r_g (motor revolutions per screw
// revolution, eq. 7.6).
struct Drive {
  double pitch_mm = 0;    // p, mm per screw revolution
  double gear_ratio = 0;  // r_g
};

// Seed 004, 7.5.1: a stepper motor of n_s steps per revolution moves the
// table a distance x at a feed f_r.
struct OpenLoopInput {
  Drive drive;
  std::int64_t steps_per_rev = 0;  // n_s, a whole number (7.3)
  double distance_mm = 0;          // x; negative moves the other way
  double feed_mm_per_min = 0;      // f_r = v_t
};

struct OpenLoop {
  double step_angle_deg = 0;       // alpha = 360 / n_s (7.3)
  double screw_angle_deg = 0;      // A = 360 x / p (7.7)
  double motor_angle_deg = 0;      // A_m = r_g A (7.6)
  double pulses = 0;               // n_p = n_s x r_g / p (7.8), as computed
  std::int64_t whole_pulses = 0;   // n_p rounded: a motor takes whole steps
  double distance_reached_mm = 0;  // x of the whole pulses (7.8 inverted)
  double screw_rpm = 0;            // N = f_r / p (7.10)
  double motor_rpm = 0;            // N_m = r_g N (7.6)
  double pulse_frequency_hz = 0;   // f_p = f_r n_s r_g / (60 p) (7.11)
};

Checked<OpenLoop> open_loop(const OpenLoopInput& in);

// Seed 004, 7.5.2: a servomotor with an encoder of n_s slots on the lead
// screw (the seed's eq. 7.14 and example 7.2 count the encoder on the screw,
// so the gear ratio only sets the motor speed).
struct ClosedLoopInput {
  Drive drive;
  std::int64_t encoder_slots = 0;  // n_s, pulses per encoder revolution
  double distance_mm = 0;          // x
  double feed_mm_per_min = 0;      // f_r
};

struct ClosedLoop {
  double slot_angle_deg = 0;       // alpha = 360 / n_s (7.12)
  double screw_angle_deg = 0;      // A = 360 x / p (7.7)
  double pulses = 0;               // n_p = A / alpha = x n_s / p (7.13, 7.14)
  std::int64_t whole_pulses = 0;   // the count the control waits for
  double distance_reached_mm = 0;  // x = p n_p / n_s of the whole count (7.14)
  double pulse_frequency_hz = 0;   // f_p = f_r n_s / (60 p) (7.15)
  double screw_rpm = 0;            // N = f_r / p (7.10)
  double motor_rpm = 0;            // N_m = r_g N (7.6)
};

Checked<ClosedLoop> closed_loop(const ClosedLoopInput& in);

// Seed 004, 7.5.3: control resolution, accuracy and repeatability of an axis.
struct PrecisionInput {
  Drive drive;
  std::int64_t steps_per_rev = 0;  // n_s: motor steps or encoder slots
  double travel_mm = 0;            // L, the axis travel
  std::int64_t bits = 0;           // B, bits of the position register, 1..64
  double sigma_mm = 0;             // standard deviation of the mechanical errors
};

struct Precision {
  double cr1_mm = 0;                 // CR_1 = p / (n_s r_g), the mechanics (7.16)
  double cr2_mm = 0;                 // CR_2 = L / (2^B - 1), the register (7.17)
  double control_resolution_mm = 0;  // CR = max(CR_1, CR_2) (7.18)
  bool limited_by_register = false;  // CR_2 > CR_1: the seed's criterion fails
  double accuracy_mm = 0;            // CR / 2 + 3 sigma (7.19)
  double repeatability_mm = 0;       // +/- 3 sigma (7.20), the half width
};

Checked<Precision> precision(const PrecisionInput& in);

// Seed 004, 7.4: spindle speed from cutting speed (7.1) and, for a cutter of
// n_f teeth at a chip load f, the feed rate (7.2). The seed's 7.1 needs v and
// D in one length unit; here v is in m/min (as tool makers give it) and D in
// mm, so N = 1000 v / (pi D).
struct CuttingInput {
  double speed_m_per_min = 0;          // v
  double diameter_mm = 0;              // D
  std::optional<std::int64_t> teeth;   // n_f; with chip_load or not at all
  std::optional<double> chip_load_mm;  // f, mm per tooth
};

struct Cutting {
  double spindle_rpm = 0;                 // N = v / (pi D) (7.1)
  std::optional<double> feed_mm_per_min;  // f_r = N n_f f (7.2)
};

Checked<Cutting> cutting(const CuttingInput& in);

// Seed 004, table 7.4: each decimal digit as four binary digits.
struct BcdDigit {
  int digit = 0;
  std::string bits;               // "0101"
  std::uint64_t place_value = 0;  // digit times its power of ten
};

struct Bcd {
  std::uint64_t value = 0;       // the sum of the place values
  std::vector<BcdDigit> digits;  // most significant first
  std::string code;              // the nibbles separated by spaces: "0001 0010 0101 0000"
};

// The BCD code of a decimal numeral such as "1250" or "07000" (leading zeros
// are digits on the tape too). At most kBcdMaxDigits digits; no sign, point
// or exponent.
inline constexpr std::size_t kBcdMaxDigits = 19;

Checked<Bcd> bcd(std::string_view numeral);

}  // namespace usina::sim
