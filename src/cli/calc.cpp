// usina calc: the positioning and cutting calculators of seed 004 (issue 6).
//
// Units throughout: lengths in mm, feeds in mm/min, rotation in rev/min,
// pulse trains in Hz (pulses per second), angles in degrees; the cutting
// speed of `calc cutting` in m/min. Text output names each figure in words,
// its formula in the seed's symbols, the value with its unit and the seed's
// equation number.
//
// `--format json` prints one object; these field names are stable:
//   every subcommand   {"calculation": NAME, "inputs": {...}, "results": {...}}
//   open-loop          inputs:  pitch_mm, gear_ratio, steps_per_rev, distance_mm,
//                               feed_mm_per_min
//                      results: step_angle_deg, screw_angle_deg, motor_angle_deg, pulses,
//                               whole_pulses, distance_reached_mm, screw_rpm, motor_rpm,
//                               pulse_frequency_hz
//   closed-loop        inputs:  pitch_mm, gear_ratio, encoder_slots, distance_mm,
//                               feed_mm_per_min
//                      results: slot_angle_deg, screw_angle_deg, pulses, whole_pulses,
//                               distance_reached_mm, pulse_frequency_hz, screw_rpm, motor_rpm
//   precision          inputs:  pitch_mm, gear_ratio, steps_per_rev, travel_mm, bits, sigma_mm
//                      results: cr1_mm, cr2_mm, control_resolution_mm, limited_by
//                               ("mechanics" or "register"), accuracy_mm, repeatability_mm
//                               (the half width of +/- 3 sigma)
//   cutting            inputs:  speed_m_per_min, diameter_mm, teeth, chip_load_mm (the last
//                               two null when not given)
//                      results: spindle_rpm, feed_mm_per_min (null without teeth and chip load)
//   bcd                inputs:  numeral (the text given)
//                      results: value, code ("0001 0010 0101 0000"),
//                               digits: [{digit, bits, place_value}]
// NAME is open_loop, closed_loop, precision, cutting or bcd.
//
// Numbers are read as text and parsed here, so that every bad value (missing,
// not a number, not whole, out of range) is reported the same way:
// "usina: error: calc SUBCOMMAND: ..." on standard error, nothing on standard
// output, exit status 2.
#include "sim/calc.hpp"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/deprecated_option.hpp"
#include "cli/verbs.hpp"
#include "sim/calc_json.hpp"

namespace usina::cli {
namespace {

using nlohmann::json;

constexpr int kBadInput = 2;

// A number flag, kept as the text the user typed; `old` is its deprecated
// spelling, when it has one (docs/gen.md, "Names").
struct Flag {
  std::string text;
  CLI::Option* option = nullptr;
  CLI::Option* old = nullptr;
};

void add_number(CLI::App& cmd, Flag& flag, const std::string& name, const std::string& unit,
                const std::string& help, const std::string& old_name = "") {
  flag.option = cmd.add_option(name, flag.text, help)->type_name(unit);
  if (!old_name.empty()) flag.old = add_deprecated_option(cmd, old_name, flag.option, flag.text);
}

void add_format(CLI::App& cmd, std::string& format) {
  cmd.add_option("--format", format,
                 "text, or json: one object of the calculation's name, inputs and results")
      ->check(CLI::IsMember({"text", "json"}))
      ->capture_default_str();
}

void fail(std::string_view verb, std::string_view message) {
  fmt::print(stderr, "usina: error: calc {}: {}\n", verb, message);
  set_exit_status(kBadInput);
}

// Reads flags as numbers, reporting every bad one; ok() says whether all were good.
class Reader {
 public:
  explicit Reader(std::string_view verb) : verb_(verb) {}

  bool ok() const { return ok_; }

  static bool given(const Flag& f) {
    return f.option->count() + (f.old != nullptr ? f.old->count() : 0) > 0;
  }

  double real(const Flag& f) {
    if (!present(f)) return 0;
    std::string_view s = f.text;
    if (s.starts_with('+')) s.remove_prefix(1);
    double v = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (s.empty() || ec != std::errc{} || end != s.data() + s.size() || !std::isfinite(v)) {
      const bool comma = f.text.find(',') != std::string::npos;
      if (ec == std::errc::result_out_of_range) {
        bad(f, fmt::format("{} is out of the range of a number", f.text));
      } else {
        bad(f, fmt::format("'{}' is not a number{}", f.text,
                           comma ? " (write the decimal point as '.')" : ""));
      }
      return 0;
    }
    return v;
  }

  std::int64_t whole(const Flag& f) {
    if (!present(f)) return 0;
    std::string_view s = f.text;
    if (s.starts_with('+')) s.remove_prefix(1);
    std::int64_t v = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (!s.empty() && ec == std::errc{} && end == s.data() + s.size()) return v;
    if (ec == std::errc::result_out_of_range) {
      bad(f, fmt::format("{} is too large", f.text));
    } else {
      bad(f, fmt::format("'{}' is not a whole number", f.text));
    }
    return 0;
  }

 private:
  bool present(const Flag& f) {
    if (given(f)) return true;
    fail(verb_, fmt::format("{} is required", f.option->get_name()));
    ok_ = false;
    return false;
  }

  void bad(const Flag& f, std::string_view why) {
    fail(verb_, fmt::format("{}: {}", f.option->get_name(), why));
    ok_ = false;
  }

  std::string_view verb_;
  bool ok_ = true;
};

// A figure for a machinist: six significant digits, no "-0".
std::string num(double v) {
  return fmt::format("{:.6g}", v == 0 ? 0.0 : v);
}

// One line of text output: the figure in words, its formula, value, unit and
// the seed's equation.
struct Row {
  std::string_view what;
  std::string_view formula;
  std::string value;
  std::string_view unit;
  std::string_view equation;
};

void print_rows(std::string_view title, const std::string& given, const std::vector<Row>& rows) {
  fmt::print("{}\n  given: {}\n", title, given);
  for (const Row& r : rows) {
    fmt::print("  {:<20} {:<28} = {:>10} {:<15} ({})\n", r.what, r.formula, r.value, r.unit,
               r.equation);
  }
}

template <typename T>
bool checked(std::string_view verb, const sim::Checked<T>& r) {
  if (!r) fail(verb, r.error());
  return r.has_value();
}

// Rows shared by both loops when the move is not a whole number of pulses.
void add_whole_pulse_rows(std::vector<Row>& rows, double pulses, std::int64_t whole,
                          double reached) {
  if (pulses == static_cast<double>(whole)) return;
  rows.push_back({"whole pulses", "n_p rounded", fmt::format("{}", whole), "pulses", "a count"});
  rows.push_back({"distance reached", "x of the whole pulses", num(reached), "mm", "eq. 7.8"});
}

// --- open loop ----------------------------------------------------------------

struct OpenLoopFlags {
  Flag pitch, gear_ratio, steps, distance, feed;
  std::string format = "text";
};

void print_open_loop(const sim::OpenLoopInput& in, const sim::OpenLoop& r) {
  std::vector<Row> rows = {
      {"step angle", "alpha = 360 / n_s", num(r.step_angle_deg), "deg per step", "eq. 7.3"},
      {"screw rotation", "A = 360 x / p", num(r.screw_angle_deg), "deg", "eq. 7.7"},
      {"motor rotation", "A_m = r_g A", num(r.motor_angle_deg), "deg", "eq. 7.6"},
      {"pulses", "n_p = n_s x r_g / p", num(r.pulses), "pulses", "eq. 7.8"},
      {"screw speed", "N = f_r / p", num(r.screw_rpm), "rev/min", "eq. 7.10"},
      {"motor speed", "N_m = r_g N", num(r.motor_rpm), "rev/min", "eq. 7.6"},
      {"pulse frequency", "f_p = f_r n_s r_g / (60 p)", num(r.pulse_frequency_hz), "Hz",
       "eq. 7.11"},
  };
  add_whole_pulse_rows(rows, r.pulses, r.whole_pulses, r.distance_reached_mm);
  print_rows("open loop: stepper motor driving the lead screw (seed 004, 7.5.1)",
             fmt::format("pitch p = {} mm/rev, gear ratio r_g = {}, n_s = {} steps/rev, x = {} mm, "
                         "f_r = {} mm/min",
                         num(in.drive.pitch_mm), num(in.drive.gear_ratio), in.steps_per_rev,
                         num(in.distance_mm), num(in.feed_mm_per_min)),
             rows);
}

void run_open_loop(const OpenLoopFlags& f) {
  Reader read("open-loop");
  const sim::OpenLoopInput in{{read.real(f.pitch), read.real(f.gear_ratio)},
                              read.whole(f.steps),
                              read.real(f.distance),
                              read.real(f.feed)};
  if (!read.ok()) return;
  const auto r = sim::open_loop(in);
  if (!checked("open-loop", r)) return;
  if (f.format == "text") return print_open_loop(in, *r);
  fmt::print("{}\n", sim::calc_json(in, *r).dump(2));
}

void add_open_loop(CLI::App& calc) {
  auto f = std::make_shared<OpenLoopFlags>();
  CLI::App* cmd = calc.add_subcommand(
      "open-loop", "stepper motor: pulses, speeds and pulse frequency of a move (7.3-7.11)");
  add_number(*cmd, f->pitch, "--pitch", "MM", "lead screw pitch p, mm per revolution (required)");
  add_number(*cmd, f->gear_ratio, "--gear-ratio", "R",
             "motor revolutions per screw revolution r_g (required)");
  add_number(*cmd, f->steps, "--steps", "N", "motor steps per revolution n_s (required)");
  add_number(*cmd, f->distance, "--distance", "MM", "distance x to move, mm (required)");
  add_number(*cmd, f->feed, "--feed", "MM/MIN", "table feed f_r, mm/min (required)");
  add_format(*cmd, f->format);
  cmd->callback([f] { run_open_loop(*f); });
}

// --- closed loop --------------------------------------------------------------

struct ClosedLoopFlags {
  Flag pitch, gear_ratio, slots, distance, feed;
  std::string format = "text";
};

void print_closed_loop(const sim::ClosedLoopInput& in, const sim::ClosedLoop& r) {
  std::vector<Row> rows = {
      {"slot angle", "alpha = 360 / n_s", num(r.slot_angle_deg), "deg per slot", "eq. 7.12"},
      {"screw rotation", "A = 360 x / p", num(r.screw_angle_deg), "deg", "eq. 7.7"},
      {"encoder pulses", "n_p = A / alpha = x n_s / p", num(r.pulses), "pulses", "eq. 7.13, 7.14"},
      {"pulse frequency", "f_p = f_r n_s / (60 p)", num(r.pulse_frequency_hz), "Hz", "eq. 7.15"},
      {"screw speed", "N = f_r / p", num(r.screw_rpm), "rev/min", "eq. 7.10"},
      {"motor speed", "N_m = r_g f_r / p", num(r.motor_rpm), "rev/min", "eq. 7.6, 7.10"},
  };
  add_whole_pulse_rows(rows, r.pulses, r.whole_pulses, r.distance_reached_mm);
  print_rows("closed loop: servomotor, encoder on the lead screw (seed 004, 7.5.2)",
             fmt::format("pitch p = {} mm/rev, gear ratio r_g = {}, n_s = {} slots/rev, x = {} mm, "
                         "f_r = {} mm/min",
                         num(in.drive.pitch_mm), num(in.drive.gear_ratio), in.encoder_slots,
                         num(in.distance_mm), num(in.feed_mm_per_min)),
             rows);
}

void run_closed_loop(const ClosedLoopFlags& f) {
  Reader read("closed-loop");
  const sim::ClosedLoopInput in{{read.real(f.pitch), read.real(f.gear_ratio)},
                                read.whole(f.slots),
                                read.real(f.distance),
                                read.real(f.feed)};
  if (!read.ok()) return;
  const auto r = sim::closed_loop(in);
  if (!checked("closed-loop", r)) return;
  if (f.format == "text") return print_closed_loop(in, *r);
  fmt::print("{}\n", sim::calc_json(in, *r).dump(2));
}

void add_closed_loop(CLI::App& calc) {
  auto f = std::make_shared<ClosedLoopFlags>();
  CLI::App* cmd = calc.add_subcommand(
      "closed-loop", "servomotor and encoder: encoder pulses, frequency, motor speed (7.12-7.15)");
  add_number(*cmd, f->pitch, "--pitch", "MM", "lead screw pitch p, mm per revolution (required)");
  add_number(*cmd, f->gear_ratio, "--gear-ratio", "R",
             "motor revolutions per screw revolution r_g (required)");
  add_number(*cmd, f->slots, "--encoder-slots", "N",
             "encoder slots (pulses) per screw revolution n_s (required)");
  add_number(*cmd, f->distance, "--distance", "MM", "distance x to move, mm (required)");
  add_number(*cmd, f->feed, "--feed", "MM/MIN", "table feed f_r, mm/min (required)");
  add_format(*cmd, f->format);
  cmd->callback([f] { run_closed_loop(*f); });
}

// --- precision ----------------------------------------------------------------

struct PrecisionFlags {
  Flag pitch, gear_ratio, steps, travel, bits, sigma;
  std::string format = "text";
};

void print_precision(const sim::PrecisionInput& in, const sim::Precision& r) {
  const std::vector<Row> rows = {
      {"CR1, mechanics", "p / (n_s r_g)", num(r.cr1_mm), "mm", "eq. 7.16"},
      {"CR2, register", "L / (2^B - 1)", num(r.cr2_mm), "mm", "eq. 7.17"},
      {"control resolution", "CR = max(CR1, CR2)", num(r.control_resolution_mm), "mm", "eq. 7.18"},
      {"accuracy", "CR / 2 + 3 sigma", num(r.accuracy_mm), "mm", "eq. 7.19"},
      {"repeatability", "+/- 3 sigma", "±" + num(r.repeatability_mm), "mm", "eq. 7.20"},
  };
  print_rows("precision of an axis: control resolution, accuracy, repeatability (seed 004, 7.5.3)",
             fmt::format("p = {} mm/rev, r_g = {}, n_s = {} steps/rev, travel L = {} mm, "
                         "B = {} bits, sigma = {} mm",
                         num(in.drive.pitch_mm), num(in.drive.gear_ratio), in.steps_per_rev,
                         num(in.travel_mm), in.bits, num(in.sigma_mm)),
             rows);
  fmt::print("  limited by: {}\n",
             r.limited_by_register
                 ? "the register bits (CR2 > CR1): more bits would make the axis finer"
                 : "the mechanics (CR2 <= CR1), as the seed recommends");
}

void run_precision(const PrecisionFlags& f) {
  Reader read("precision");
  const sim::PrecisionInput in{{read.real(f.pitch), read.real(f.gear_ratio)},
                               read.whole(f.steps),
                               read.real(f.travel),
                               read.whole(f.bits),
                               read.real(f.sigma)};
  if (!read.ok()) return;
  const auto r = sim::precision(in);
  if (!checked("precision", r)) return;
  if (f.format == "text") return print_precision(in, *r);
  fmt::print("{}\n", sim::calc_json(in, *r).dump(2));
}

void add_precision(CLI::App& calc) {
  auto f = std::make_shared<PrecisionFlags>();
  CLI::App* cmd = calc.add_subcommand(
      "precision", "control resolution, accuracy and repeatability of an axis (7.16-7.20)");
  add_number(*cmd, f->pitch, "--pitch", "MM", "lead screw pitch p, mm per revolution (required)");
  add_number(*cmd, f->gear_ratio, "--gear-ratio", "R",
             "motor revolutions per screw revolution r_g (required)");
  add_number(*cmd, f->steps, "--steps", "N",
             "motor steps or encoder slots per revolution n_s (required)");
  add_number(*cmd, f->travel, "--travel", "MM", "axis travel L, mm (required)");
  add_number(*cmd, f->bits, "--bits", "B", "bits of the position register, 1 to 64 (required)");
  add_number(*cmd, f->sigma, "--sigma", "MM",
             "standard deviation of the mechanical errors, mm (required)");
  add_format(*cmd, f->format);
  cmd->callback([f] { run_precision(*f); });
}

// --- cutting ------------------------------------------------------------------

struct CuttingFlags {
  Flag speed, diameter, teeth, chip_load;
  std::string format = "text";
};

void print_cutting(const sim::CuttingInput& in, const sim::Cutting& r) {
  std::vector<Row> rows = {
      {"spindle speed", "N = 1000 v / (pi D)", num(r.spindle_rpm), "rev/min", "eq. 7.1"}};
  std::string given = fmt::format("cutting speed v = {} m/min, cutter diameter D = {} mm",
                                  num(in.speed_m_per_min), num(in.diameter_mm));
  if (r.feed_mm_per_min) {
    rows.push_back({"feed rate", "f_r = N n_f f", num(*r.feed_mm_per_min), "mm/min", "eq. 7.2"});
    given += fmt::format(", n_f = {} teeth, chip load f = {} mm per tooth", *in.teeth,
                         num(*in.chip_load_mm));
  }
  print_rows("cutting conditions: spindle speed and feed rate (seed 004, 7.4)", given, rows);
}

void run_cutting(const CuttingFlags& f) {
  Reader read("cutting");
  sim::CuttingInput in{read.real(f.speed), read.real(f.diameter), std::nullopt, std::nullopt};
  if (Reader::given(f.teeth)) in.teeth = read.whole(f.teeth);
  if (Reader::given(f.chip_load)) in.chip_load_mm = read.real(f.chip_load);
  if (!read.ok()) return;
  const auto r = sim::cutting(in);
  if (!checked("cutting", r)) return;
  if (f.format == "text") return print_cutting(in, *r);
  fmt::print("{}\n", sim::calc_json(in, *r).dump(2));
}

void add_cutting(CLI::App& calc) {
  auto f = std::make_shared<CuttingFlags>();
  CLI::App* cmd = calc.add_subcommand(
      "cutting", "spindle speed from cutting speed, feed rate from chip load (7.1, 7.2)");
  add_number(*cmd, f->speed, "--cutting-speed", "M/MIN", "cutting speed v, m/min (required)",
             "--speed");
  add_number(*cmd, f->diameter, "--tool-diameter", "MM", "cutter diameter D, mm (required)",
             "--diameter");
  add_number(*cmd, f->teeth, "--flutes", "N", "flutes (teeth) of the cutter n_f (with --chip-load)",
             "--teeth");
  add_number(*cmd, f->chip_load, "--chip-load", "MM", "chip load f, mm per tooth (with --flutes)");
  add_format(*cmd, f->format);
  cmd->callback([f] { run_cutting(*f); });
}

// --- bcd ----------------------------------------------------------------------

struct BcdFlags {
  std::string numeral;
  std::string format = "text";
};

void print_bcd(const sim::Bcd& r) {
  fmt::print("BCD of {} (seed 004, table 7.4: each decimal digit as four binary digits)\n",
             r.value);
  fmt::print("  {:>5}  {:>6}  {:>20}\n", "digit", "binary", "value");
  for (const sim::BcdDigit& d : r.digits)
    fmt::print("  {:>5}  {:>6}  {:>20}\n", d.digit, d.bits, d.place_value);
  fmt::print("  {:>5}  {:>6}  {:>20}\n", "sum", "", r.value);
  fmt::print("  code: {}\n", r.code);
}

void run_bcd(const BcdFlags& f) {
  const auto r = sim::bcd(f.numeral);
  if (!checked("bcd", r)) return;
  if (f.format == "text") return print_bcd(*r);
  fmt::print("{}\n", sim::calc_json(f.numeral, *r).dump(2));
}

void add_bcd(CLI::App& calc) {
  auto f = std::make_shared<BcdFlags>();
  CLI::App* cmd = calc.add_subcommand("bcd", "binary-coded decimal of a whole number (table 7.4)");
  // Not ->required(): sim::bcd says what is missing, with the exit status of any bad input.
  cmd->add_option("number", f->numeral, "a whole number of at most 19 digits, such as 1250");
  add_format(*cmd, f->format);
  cmd->callback([f] { run_bcd(*f); });
}

}  // namespace

void add_calc(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand(
      "calc",
      "positioning and cutting calculators of a CNC axis and a cut (mm, mm/min, rev/min, Hz)");
  cmd->require_subcommand(1);
  add_open_loop(*cmd);
  add_closed_loop(*cmd);
  add_precision(*cmd);
  add_cutting(*cmd);
  add_bcd(*cmd);
}

}  // namespace usina::cli
