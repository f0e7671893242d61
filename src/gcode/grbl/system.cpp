// Grbl's `$` system commands ([sys], [cmd] of docs/grbl.md §4): reports do
// nothing, settings are recorded, `$H` and `$J=` become a move for the
// interpreter, anything else is error:3.
#include <charconv>
#include <cmath>
#include <set>
#include <string>

#include <fmt/format.h>

#include "gcode/grbl/dialect.hpp"

namespace usina::gcode::grbl {
namespace {

// The settings of Grbl 1.1 ([set]); `$x=` of any other x is error:3.
const std::set<int>& known_settings() {
  static const std::set<int> s = {0,   1,   2,   3,   4,   5,   6,   10,  11,  12, 13,  20,
                                  21,  22,  23,  24,  25,  26,  27,  30,  31,  32, 100, 101,
                                  102, 110, 111, 112, 120, 121, 122, 130, 131, 132};
  return s;
}

// Grbl's defaults (defaults.h, DEFAULTS_GENERIC) for the settings usina uses.
double default_setting(int n) {
  switch (n) {
  case 0: return 10;
  case 12: return 0.002;
  case 27: return 1.0;
  case 100:
  case 101:
  case 102: return 250.0;  // steps/mm
  case 110:
  case 111:
  case 112: return 500.0;  // mm/min
  case 130:
  case 131:
  case 132: return 200.0;  // mm
  default: return 0.0;
  }
}

// MAX_STEP_RATE_HZ (config.h; off in the default build): steps/mm × max
// rate (mm/min) may not pass it × 60. Grbl checks the setting being written
// against the other one's present value.
Checked step_rate(int n, double v, std::uint32_t col, const Settings& settings,
                  const OptionValues& options) {
  const auto it = options.find("max_step_rate");
  if (it == options.end() || it->second == "off") return {};
  const double limit_hz = std::stod(it->second);
  const bool steps = n >= 100 && n <= 102;
  if (!steps && !(n >= 110 && n <= 112)) return {};
  const double other = settings.get(steps ? n + 10 : n - 10);
  if (v * other <= limit_hz * 60.0) return {};
  const double spm = steps ? v : other;
  const double rate = steps ? other : v;
  return tl::unexpected(
      Failure{12, col,
              fmt::format("{} steps/mm at {} mm/min is {:.0f} steps/s, above the build's "
                          "MAX_STEP_RATE_HZ {}",
                          spm, rate, spm * rate / 60.0, limit_hz)});
}

Checked setting(std::string_view text, std::uint32_t col, Settings& settings,
                const OptionValues& options) {
  const std::size_t eq = text.find('=');
  int n = -1;
  const auto r = std::from_chars(text.data() + 1, text.data() + eq, n);
  if (r.ec != std::errc{} || r.ptr != text.data() + eq || !known_settings().count(n)) {
    return tl::unexpected(
        Failure{3, col, fmt::format("{} is not a Grbl 1.1 setting", text.substr(0, eq))});
  }
  std::vector<Word> words;
  // The value is read as Grbl's read_float does: an 'X' stands in for a letter.
  // (Appended, not "X" + string: GCC 12 at -O3 warns wrongly of an overlap.)
  std::string as_word = "X";
  as_word += text.substr(eq + 1);
  std::vector<std::uint32_t> cols(as_word.size(), col);
  if (!read_words(as_word, cols, words) || words.size() != 1) {
    return tl::unexpected(Failure{2, col, fmt::format("${}= needs a number", n)});
  }
  const double v = words[0].value;
  if (v < 0)
    return tl::unexpected(Failure{4, col, fmt::format("${}={} must not be negative", n, v)});
  if (n == 0 && v < 3)
    return tl::unexpected(Failure{6, col, "$0 (step pulse) must be at least 3 microseconds"});
  if (auto f = step_rate(n, v, col, settings, options); !f) return f;
  // Grbl reads the switches as whole numbers: $20=0.5 is off.
  const double whole = std::trunc(v);
  if (n == 20 && whole != 0 && settings.get(22) == 0) {
    return tl::unexpected(
        Failure{10, col, "$20=1 (soft limits) needs homing enabled ($22=1) first"});
  }
  settings.values[n] = (n == 20 || n == 22 || n == 23) ? whole : v;
  if (n == 22 && whole == 0) settings.values[20] = 0;  // Grbl turns soft limits off with homing
  return {};
}

SystemResult homing(const Modal& state, std::uint32_t col, const Settings& settings) {
  SystemResult r;
  if (settings.get(22) == 0) {
    r.failure = Failure{5, col, "$H with homing disabled ($22=0)"};
    return r;
  }
  // Grbl's homing (limits.c, no HOMING_FORCE_SET_ORIGIN) leaves each axis
  // at minus the pull-off, or, on an axis whose $23 bit homes it to the
  // negative end, at minus its travel plus the pull-off. The path there is
  // unknown: a rapid in machine coordinates stands for it.
  const double unit = state.inch ? 25.4 : 1.0;
  const int negative = static_cast<int>(settings.get(23));
  const double pull_off = settings.get(27);
  r.handed.add('G', 53);
  r.handed.add('G', 0);
  for (int a = 0; a < 3; ++a) {
    const double mm = (negative >> a) & 1 ? pull_off - settings.get(130 + a) : -pull_off;
    r.handed.add("XYZ"[a], mm / unit);
  }
  r.restore_modes = true;
  r.homing = true;
  return r;
}

bool jog_code_allowed(double code) {
  return code == 20 || code == 21 || code == 90 || code == 91 || code == 53;
}

SystemResult jog(std::string_view text, const std::vector<std::uint32_t>& cols,
                 const Modal& state) {
  SystemResult r;
  std::vector<Word> words;
  const std::string_view body = text.substr(3);
  const std::vector<std::uint32_t> body_cols(cols.begin() + 3, cols.end());
  if (auto f = read_words(body, body_cols, words); !f) {
    r.failure = f.error();
    return r;
  }
  bool inch = state.inch;
  // Explicit: a jog before may have left the interpreter in its own mode.
  int distance = state.incremental ? 91 : 90;
  bool g53 = false;
  std::map<char, double> values;
  for (const Word& w : words) {
    if (w.letter == 'G' && jog_code_allowed(w.value)) {
      if (w.value == 20 || w.value == 21) inch = w.value == 20;
      if (w.value == 90 || w.value == 91) distance = w.value == 90 ? 90 : 91;
      if (w.value == 53) g53 = true;
      continue;
    }
    if (std::string_view("XYZFN").find(w.letter) == std::string_view::npos) {
      r.failure =
          Failure{16, w.col, fmt::format("{}{} is not allowed in a jog", w.letter, w.value)};
      return r;
    }
    if (values.count(w.letter)) {
      r.failure = Failure{25, w.col, fmt::format("{} word appears twice in the jog", w.letter)};
      return r;
    }
    values[w.letter] = w.value;
  }
  if (!values.count('F')) {
    r.failure = Failure{22, cols.front(), "a jog needs its own feed rate (F)"};
    return r;
  }
  if (!values.count('X') && !values.count('Y') && !values.count('Z')) return r;
  // The jog's values in the program's current units: the jog's G20/G21 is
  // for the jog only.
  const double scale = inch == state.inch ? 1.0 : (inch ? 25.4 : 1.0 / 25.4);
  r.handed.add('G', 1);
  if (state.inverse_time) r.handed.add('G', 94);
  r.handed.add('G', distance);
  if (g53) r.handed.add('G', 53);
  for (char a : std::string_view("XYZF")) {
    if (values.count(a)) r.handed.add(a, values[a] * scale);
  }
  r.restore_modes = true;
  r.jog = true;
  return r;
}

// $RST=$ (settings), $RST=# (G54-G59, G28, G30 zeroed), $RST=* (both);
// each ends in a soft reset, which puts the parser in its power-on state
// (gc_init: G92 and G43.1 cleared, F undefined) and keeps the position.
SystemResult restore(std::string_view what, std::uint32_t col, Settings& settings) {
  SystemResult r;
  if (what != "$" && what != "#" && what != "*") {
    r.failure = Failure{3, col, "$RST= takes $, # or *"};
    return r;
  }
  if (what != "#") settings = Settings{};
  if (what != "$") {
    // The interpreter's parameters: G28 5161, G30 5181, G54..G59 5221 + 20 n.
    for (int base : {5161, 5181, 5221, 5241, 5261, 5281, 5301, 5321}) {
      for (int a = 0; a < 3; ++a)
        r.handed.assigns.push_back({base + a, {}, 0.0, 0});
    }
  }
  // G0: grbl/reader.cpp puts it on the next line moving with the modal motion.
  for (double g : {54.0, 17.0, 21.0, 90.0, 94.0, 49.0, 92.1})
    r.handed.add('G', g);
  r.handed.add('M', 5);
  r.handed.add('M', 9);
  r.reset = true;
  r.warnings.push_back(
      fmt::format("$RST={} ends in a soft reset: the modes are Grbl's power-on ones, F is "
                  "undefined{}",
                  what, what == "$" ? ", the settings Grbl's defaults" : ", the offsets zero"));
  return r;
}

// A start-up block ($Nx=): stored, not run. Grbl checks its length against
// the EEPROM line (80 bytes with the terminator) before the block itself;
// with the default 80-byte line buffer a line cannot be that long.
Checked startup_line(const CodeIndex& codes, const OptionValues& options, std::string_view text,
                     const std::vector<std::uint32_t>& cols, const Modal& state) {
  constexpr std::size_t kEepromLine = 80;
  if (text.size() + 1 > kEepromLine) {
    return tl::unexpected(Failure{14, cols.front(),
                                  fmt::format("a start-up line of {} characters; Grbl stores {}",
                                              text.size(), kEepromLine - 1)});
  }
  std::vector<Word> words;
  const std::vector<std::uint32_t> body_cols(cols.begin() + 4, cols.end());
  if (auto f = read_words(text.substr(4), body_cols, words); !f) return f;
  Modal copy = state;
  Accepted ignored;
  return check_block(codes, options, words, copy, ignored);
}

bool is_report(std::string_view t) {
  return t == "$" || t == "$$" || t == "$#" || t == "$G" || t == "$I" || t == "$N" || t == "$X";
}

}  // namespace

double Settings::get(int n) const {
  auto it = values.find(n);
  return it == values.end() ? default_setting(n) : it->second;
}

Travel Travel::of(const Settings& s) {
  Travel t;
  t.soft_limits = s.get(20) != 0;
  t.max = {s.get(130), s.get(131), s.get(132)};
  t.arc_tolerance = s.get(12);
  return t;
}

int Travel::beyond(const core::Vec3& machine) const {
  constexpr double kRoundOff = 1e-6;  // mm: the interpreter's sums, not Grbl's floats
  for (int a = 0; a < 3; ++a) {
    if (machine[a] > kRoundOff || machine[a] < -max[a] - kRoundOff) return a;
  }
  return -1;
}

SystemResult system_command(const CodeIndex& codes, const OptionValues& options,
                            std::string_view text, const std::vector<std::uint32_t>& cols,
                            const Modal& state, Settings& settings) {
  SystemResult r;
  const std::uint32_t col = cols.front();
  if (is_report(text)) return r;
  if (text.substr(0, 5) == "$RST=") return restore(text.substr(5), col, settings);
  if (text == "$C" || text == "$SLP") {
    r.warnings.push_back(
        fmt::format("{} changes the machine, not the program: usina ignores it", text));
    return r;
  }
  if (text == "$H") return homing(state, col, settings);
  if (text.substr(0, 3) == "$J=") return jog(text, cols, state);
  // Build info text: stored by Grbl (1.1h checks no length here, only on
  // $Nx=), nothing to run.
  if (text.substr(0, 3) == "$I=") return r;
  if (text.size() >= 4 && text[1] == 'N' && (text[2] == '0' || text[2] == '1') && text[3] == '=') {
    if (auto f = startup_line(codes, options, text, cols, state); !f) r.failure = f.error();
    return r;
  }
  if (text.size() >= 2 && text[1] >= '0' && text[1] <= '9' &&
      text.find('=') != std::string_view::npos) {
    if (auto f = setting(text, col, settings, options); !f) r.failure = f.error();
    return r;
  }
  if (text.substr(0, 2) == "$J") {
    r.failure = Failure{16, col, "a jog is written $J=<words>"};
    return r;
  }
  r.failure = Failure{3, col, fmt::format("{} is not a Grbl system command", text)};
  return r;
}

}  // namespace usina::gcode::grbl
