// Grbl's `$` system commands ([sys], [cmd] of docs/grbl.md §4): reports do
// nothing, settings are recorded, `$H` and `$J=` become a move for the
// interpreter, anything else is error:3.
#include <charconv>
#include <cmath>
#include <set>

#include <fmt/format.h>

#include "gcode/dialects/grbl.hpp"

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
  default: return 0.0;
  }
}

std::string number_text(double v) {
  return fmt::format("{:.12f}", v);  // no exponent: the interpreter reads it back
}

std::optional<Failure> setting(std::string_view text, std::uint32_t col, Settings& settings) {
  const std::size_t eq = text.find('=');
  int n = -1;
  const auto r = std::from_chars(text.data() + 1, text.data() + eq, n);
  if (r.ec != std::errc{} || r.ptr != text.data() + eq || !known_settings().count(n)) {
    return Failure{3, col, fmt::format("{} is not a Grbl 1.1 setting", text.substr(0, eq))};
  }
  std::vector<Word> words;
  // The value is read as Grbl's read_float does: an 'X' stands in for a letter.
  std::string as_word = "X" + std::string(text.substr(eq + 1));
  std::vector<std::uint32_t> cols(as_word.size(), col);
  if (read_words(as_word, cols, words) || words.size() != 1) {
    return Failure{2, col, fmt::format("${}= needs a number", n)};
  }
  const double v = words[0].value;
  if (v < 0) return Failure{4, col, fmt::format("${}={} must not be negative", n, v)};
  if (n == 0 && v < 3) return Failure{6, col, "$0 (step pulse) must be at least 3 microseconds"};
  if (n == 20 && v != 0 && settings.get(22) == 0) {
    return Failure{10, col, "$20=1 (soft limits) needs homing enabled ($22=1) first"};
  }
  settings.values[n] = v;
  return std::nullopt;
}

SystemResult homing(const Modal& state, std::uint32_t col, const Settings& settings) {
  SystemResult r;
  if (settings.get(22) == 0) {
    r.failure = Failure{5, col, "$H with homing disabled ($22=0)"};
    return r;
  }
  // Grbl's default homing (positive direction, no HOMING_FORCE_SET_ORIGIN)
  // leaves the machine at minus the pull-off on each axis. The path there is
  // unknown: a rapid in machine coordinates stands for it.
  const double p = settings.get(27) / (state.inch ? 25.4 : 1.0);
  const std::string v = number_text(-p);
  r.interp_line = fmt::format("G53 G0 X{0} Y{0} Z{0}", v);
  r.restore_modes = true;
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
  if (auto f = read_words(body, body_cols, words)) {
    r.failure = f;
    return r;
  }
  bool inch = state.inch;
  // Explicit: a jog before may have left the interpreter in its own mode.
  std::string distance = state.incremental ? " G91" : " G90";
  bool g53 = false;
  std::map<char, double> values;
  for (const Word& w : words) {
    if (w.letter == 'G' && jog_code_allowed(w.value)) {
      if (w.value == 20 || w.value == 21) inch = w.value == 20;
      if (w.value == 90 || w.value == 91) distance = w.value == 90 ? " G90" : " G91";
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
  std::string line =
      fmt::format("G1{}{}{}", state.inverse_time ? " G94" : "", distance, g53 ? " G53" : "");
  for (char a : std::string_view("XYZF")) {
    if (values.count(a)) line += fmt::format(" {}{}", a, number_text(values[a] * scale));
  }
  r.interp_line = line;
  r.restore_modes = true;
  return r;
}

bool is_report(std::string_view t) {
  return t == "$" || t == "$$" || t == "$#" || t == "$G" || t == "$I" || t == "$N" || t == "$X";
}

}  // namespace

double Settings::get(int n) const {
  auto it = values.find(n);
  return it == values.end() ? default_setting(n) : it->second;
}

SystemResult system_command(const Dialect& d, const OptionValues& options, std::string_view text,
                            const std::vector<std::uint32_t>& cols, const Modal& state,
                            Settings& settings) {
  SystemResult r;
  const std::uint32_t col = cols.front();
  if (is_report(text)) return r;
  if (text == "$C" || text == "$SLP" || text == "$RST=$" || text == "$RST=#" || text == "$RST=*") {
    r.warnings.push_back(
        fmt::format("{} changes the machine, not the program: usina ignores it", text));
    return r;
  }
  if (text == "$H") return homing(state, col, settings);
  if (text.substr(0, 3) == "$J=") return jog(text, cols, state);
  if (text.substr(0, 3) == "$I=") return r;  // build info text: stored by Grbl, nothing to run
  if (text.size() >= 4 && text[1] == 'N' && (text[2] == '0' || text[2] == '1') && text[3] == '=') {
    // A start-up block: checked as a block, run only at the next reset.
    std::vector<Word> words;
    const std::vector<std::uint32_t> body_cols(cols.begin() + 4, cols.end());
    r.failure = read_words(text.substr(4), body_cols, words);
    if (!r.failure) {
      Modal copy = state;
      Accepted ignored;
      r.failure = check_block(d, options, words, copy, ignored);
    }
    return r;
  }
  if (text.size() >= 2 && text[1] >= '0' && text[1] <= '9' &&
      text.find('=') != std::string_view::npos) {
    r.failure = setting(text, col, settings);
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
