// Seed 004: the positioning-system figures of 7.5 and the cutting equations.
#include "sim/calc.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <numbers>

#include <fmt/format.h>

namespace usina::sim {
namespace {

using Error = std::optional<std::string>;

// Above 2^53 a double no longer holds every whole number, so a pulse count
// there would be a guess.
constexpr double kMaxPulses = 9007199254740992.0;

Error need_positive(std::string_view what, double v, std::string_view unit) {
  if (std::isfinite(v) && v > 0) return std::nullopt;
  return fmt::format("{} must be a number greater than 0 {}, not {}", what, unit, v);
}

Error need_finite(std::string_view what, double v, std::string_view unit) {
  if (std::isfinite(v)) return std::nullopt;
  return fmt::format("{} must be a finite number of {}, not {}", what, unit, v);
}

Error need_count(std::string_view what, std::int64_t n) {
  if (n >= 1) return std::nullopt;
  return fmt::format("{} must be a whole number of at least 1, not {}", what, n);
}

// The first of the errors, all of which were checked.
Error first(std::initializer_list<Error> errors) {
  for (const Error& e : errors) {
    if (e) return e;
  }
  return std::nullopt;
}

bool all_finite(std::initializer_list<double> values) {
  return std::ranges::all_of(values, [](double v) { return std::isfinite(v); });
}

std::string overflow() {
  return "the figures overflow a double for these inputs; check their magnitudes";
}

Error check_drive(const Drive& d) {
  return first({need_positive("the screw pitch p", d.pitch_mm, "mm/rev"),
                need_positive("the gear ratio r_g", d.gear_ratio, "motor rev per screw rev")});
}

Error check_move(const Drive& d, std::string_view count_name, std::int64_t count, double x,
                 double feed) {
  return first({check_drive(d), need_count(count_name, count),
                need_finite("the distance x", x, "mm"),
                need_positive("the feed f_r", feed, "mm/min")});
}

// The pulse count nearest `pulses`, or why there is none.
Error whole_count(double pulses, std::int64_t& whole) {
  if (std::abs(pulses) > kMaxPulses) {
    return fmt::format("the move needs {:g} pulses, more than a control counts exactly (2^53)",
                       pulses);
  }
  whole = std::llround(pulses);
  return std::nullopt;
}

}  // namespace

Checked<OpenLoop> open_loop(const OpenLoopInput& in) {
  if (Error e = check_move(in.drive, "the steps per revolution n_s", in.steps_per_rev,
                           in.distance_mm, in.feed_mm_per_min)) {
    return tl::unexpected(*e);
  }
  const double p = in.drive.pitch_mm;
  const double rg = in.drive.gear_ratio;
  const auto ns = static_cast<double>(in.steps_per_rev);
  const double x = in.distance_mm;
  const double fr = in.feed_mm_per_min;
  OpenLoop r;
  r.step_angle_deg = 360.0 / ns;                     // (7.3)
  r.screw_angle_deg = 360.0 * x / p;                 // (7.7) solved for A
  r.motor_angle_deg = rg * r.screw_angle_deg;        // (7.6): A_m = r_g A
  r.pulses = ns * x * rg / p;                        // (7.8), second form
  r.screw_rpm = fr / p;                              // (7.10) solved for N
  r.motor_rpm = rg * r.screw_rpm;                    // (7.6): N_m = r_g N
  r.pulse_frequency_hz = fr * ns * rg / (60.0 * p);  // (7.11)
  if (!all_finite({r.screw_angle_deg, r.motor_angle_deg, r.pulses, r.screw_rpm, r.motor_rpm,
                   r.pulse_frequency_hz})) {
    return tl::unexpected(overflow());
  }
  if (Error e = whole_count(r.pulses, r.whole_pulses)) return tl::unexpected(*e);
  r.distance_reached_mm = static_cast<double>(r.whole_pulses) * p / (ns * rg);  // (7.8)
  return r;
}

Checked<ClosedLoop> closed_loop(const ClosedLoopInput& in) {
  if (Error e = check_move(in.drive, "the encoder slots n_s", in.encoder_slots, in.distance_mm,
                           in.feed_mm_per_min)) {
    return tl::unexpected(*e);
  }
  const double p = in.drive.pitch_mm;
  const double rg = in.drive.gear_ratio;
  const auto ns = static_cast<double>(in.encoder_slots);
  const double x = in.distance_mm;
  const double fr = in.feed_mm_per_min;
  ClosedLoop r;
  r.slot_angle_deg = 360.0 / ns;                // (7.12)
  r.screw_angle_deg = 360.0 * x / p;            // (7.7)
  r.pulses = x * ns / p;                        // (7.14) solved for n_p; equals A / alpha (7.13)
  r.pulse_frequency_hz = fr * ns / (60.0 * p);  // (7.15) solved for f_p
  r.screw_rpm = fr / p;                         // (7.10)
  // (7.6) with (7.10). The seed's example 7.2(c) prints "f_r f_r / p", a
  // misprint of r_g f_r / p: its numbers are 5(500)/6.
  r.motor_rpm = rg * r.screw_rpm;
  if (!all_finite({r.screw_angle_deg, r.pulses, r.pulse_frequency_hz, r.screw_rpm, r.motor_rpm})) {
    return tl::unexpected(overflow());
  }
  if (Error e = whole_count(r.pulses, r.whole_pulses)) return tl::unexpected(*e);
  r.distance_reached_mm = p * static_cast<double>(r.whole_pulses) / ns;  // (7.14)
  return r;
}

Checked<Precision> precision(const PrecisionInput& in) {
  Error e =
      first({check_drive(in.drive), need_count("the steps per revolution n_s", in.steps_per_rev),
             need_positive("the axis travel L", in.travel_mm, "mm")});
  if (!e && (in.bits < 1 || in.bits > 64)) {
    e = fmt::format("the register bits B must be a whole number from 1 to 64, not {}", in.bits);
  }
  if (!e && !(std::isfinite(in.sigma_mm) && in.sigma_mm >= 0)) {
    e = fmt::format("the standard deviation sigma must be a number of mm of 0 or more, not {}",
                    in.sigma_mm);
  }
  if (e) return tl::unexpected(*e);
  Precision r;
  // (7.16)
  r.cr1_mm = in.drive.pitch_mm / (static_cast<double>(in.steps_per_rev) * in.drive.gear_ratio);
  r.cr2_mm = in.travel_mm / (std::ldexp(1.0, static_cast<int>(in.bits)) -
                             1.0);                         // (7.17): 2^B points, 2^B - 1 gaps
  r.control_resolution_mm = std::max(r.cr1_mm, r.cr2_mm);  // (7.18)
  r.limited_by_register = r.cr2_mm > r.cr1_mm;
  r.accuracy_mm = r.control_resolution_mm / 2.0 + 3.0 * in.sigma_mm;  // (7.19)
  r.repeatability_mm = 3.0 * in.sigma_mm;                             // (7.20)
  if (!all_finite({r.cr1_mm, r.cr2_mm, r.accuracy_mm, r.repeatability_mm})) {
    return tl::unexpected(overflow());
  }
  return r;
}

Checked<Cutting> cutting(const CuttingInput& in) {
  Error e = first({need_positive("the cutting speed v", in.speed_m_per_min, "m/min"),
                   need_positive("the cutter diameter D", in.diameter_mm, "mm")});
  if (!e && in.teeth.has_value() != in.chip_load_mm.has_value()) {
    e = "the feed rate (7.2) needs both the number of teeth n_f and the chip load f; give both or "
        "neither";
  }
  if (!e && in.teeth) e = need_count("the number of teeth n_f", *in.teeth);
  if (!e && in.chip_load_mm) {
    e = need_positive("the chip load f", *in.chip_load_mm, "mm per tooth");
  }
  if (e) return tl::unexpected(*e);
  Cutting r;
  // (7.1) with v in m/min and D in mm: 1000 mm to the metre.
  r.spindle_rpm = 1000.0 * in.speed_m_per_min / (std::numbers::pi * in.diameter_mm);
  if (in.teeth) {
    r.feed_mm_per_min = r.spindle_rpm * static_cast<double>(*in.teeth) * *in.chip_load_mm;  // (7.2)
  }
  if (!all_finite({r.spindle_rpm, r.feed_mm_per_min.value_or(0.0)})) {
    return tl::unexpected(overflow());
  }
  return r;
}

namespace {

Error check_numeral(std::string_view s) {
  if (s.empty()) return "give the number to code in BCD, such as 1250";
  if (s.front() == '-') {
    return fmt::format(
        "{} is negative; BCD (table 7.4) codes the digits 0-9 of a number "
        "without its sign",
        s);
  }
  if (s.front() == '+') return fmt::format("{} has a sign; give the digits 0-9 only", s);
  if (s.find_first_not_of("0123456789") == std::string_view::npos) {
    if (s.size() <= kBcdMaxDigits) return std::nullopt;
    return fmt::format("{} has {} digits; give at most {}", s, s.size(), kBcdMaxDigits);
  }
  if (s.find_first_not_of("0123456789.eE+-") == std::string_view::npos) {
    return fmt::format(
        "{} is not a whole number; BCD (table 7.4) codes whole numbers, digit by "
        "digit",
        s);
  }
  return fmt::format("'{}' is not a decimal number; give the digits 0-9 only", s);
}

}  // namespace

Checked<Bcd> bcd(std::string_view numeral) {
  if (Error e = check_numeral(numeral)) return tl::unexpected(*e);
  Bcd r;
  std::uint64_t place = 1;
  for (std::size_t i = 1; i < numeral.size(); ++i)
    place *= 10;
  for (const char c : numeral) {
    BcdDigit d;
    d.digit = c - '0';
    for (int bit = 3; bit >= 0; --bit)
      d.bits += ((d.digit >> bit) & 1) != 0 ? '1' : '0';
    d.place_value = static_cast<std::uint64_t>(d.digit) * place;
    r.value += d.place_value;
    if (!r.code.empty()) r.code += ' ';
    r.code += d.bits;
    r.digits.push_back(std::move(d));
    place /= 10;
  }
  return r;
}

}  // namespace usina::sim
