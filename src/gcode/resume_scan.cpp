// A scan of a program's words and structure, line by line (resume_scan.hpp).
#include "gcode/resume_scan.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <unordered_map>

namespace usina::gcode {
namespace {

struct Frame {
  std::string kind;  // "sub", "while", "do", "repeat", "if", "WHILE", "SUB"
  std::string label;
  std::size_t line = 0;
};

// The line's text without comments, upper case ('(...)', ';' to the end,
// and romi's '#' block end).
std::string stripped(std::string_view raw, bool romi) {
  std::string out;
  int paren = 0;
  for (const char c : raw) {
    if (c == '(') ++paren;
    if (paren > 0) {
      if (c == ')') --paren;
      continue;
    }
    if (c == ';' || (romi && c == '#')) break;
    out += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  }
  return out;
}

std::optional<double> number_at(const std::string& s, std::size_t& i) {
  while (i < s.size() && s[i] == ' ')
    ++i;
  const std::size_t from = i;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  while (i < s.size() && (std::isdigit(static_cast<unsigned char>(s[i])) || s[i] == '.'))
    ++i;
  if (i == from) return std::nullopt;
  const std::string digits = s.substr(from, i - from);
  char* end = nullptr;
  const double v = std::strtod(digits.c_str(), &end);
  if (end == digits.c_str() || !std::isfinite(v)) return std::nullopt;
  return v;
}

void read_words(const std::string& s, std::string_view raw, bool romi, ScanLine& l) {
  for (std::size_t i = 0; i < s.size();) {
    const char c = s[i++];
    if (c < 'A' || c > 'Z') continue;
    auto v = number_at(s, i);
    if (!v && romi && c == 'G') v = 0.0;  // romi: a bare G is G0
    if (!v) continue;
    if (c == 'N' && !l.n) l.n = std::lround(*v);
    if (c == 'G') l.g.push_back(static_cast<int>(std::lround(*v * 10)));
    if (c == 'M') l.m.push_back(static_cast<int>(std::lround(*v)));
    if (std::string_view("XYZABCUVW").find(c) != std::string_view::npos) l.axis = true;
  }
  // romi: a lower-case x y z is an incremental move
  if (romi) {
    for (const char c : raw)
      if (c == 'x' || c == 'y' || c == 'z') l.axis = true;
  }
}

bool is_macro_line(const std::string& s) {
  return s.find("WHILE") != std::string::npos || s.find("END") != std::string::npos ||
         s.find("GOTO") != std::string::npos || s.find("IF") != std::string::npos ||
         s.find('=') != std::string::npos;
}

std::string trim(std::string_view s) {
  std::size_t a = 0, b = s.size();
  while (a < b && std::isspace(static_cast<unsigned char>(s[a])))
    ++a;
  while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1])))
    --b;
  return std::string(s.substr(a, b - a));
}

// rs274ngc and grbl O-words: "o<name> sub", "o100 while [...]"; changes the frames.
void o_word(const std::string& s, std::size_t line, std::vector<Frame>& frames) {
  std::string t = trim(s);
  if (t.empty() || t[0] != 'O') return;
  std::size_t i = 1;
  if (i < t.size() && t[i] == '<') {
    i = t.find('>', i);
    if (i == std::string::npos) return;
    ++i;
  } else {
    while (i < t.size() && std::isdigit(static_cast<unsigned char>(t[i])))
      ++i;
  }
  const std::string label = t.substr(0, i);
  while (i < t.size() && t[i] == ' ')
    ++i;
  std::size_t e = i;
  while (e < t.size() && std::isalpha(static_cast<unsigned char>(t[e])))
    ++e;
  const std::string kw = t.substr(i, e - i);
  const bool top_do = !frames.empty() && frames.back().kind == "DO" && frames.back().label == label;
  if (kw == "SUB" || kw == "WHILE" || kw == "DO" || kw == "REPEAT" || kw == "IF") {
    if (kw == "WHILE" && top_do) {
      frames.pop_back();
      return;
    }
    frames.push_back({kw, label, line});
  } else if ((kw == "ENDSUB" || kw == "ENDWHILE" || kw == "ENDREPEAT" || kw == "ENDIF") &&
             !frames.empty()) {
    frames.pop_back();
  }
}

// fanuc WHILE [..] DO n ... END n; romi (SUB n) ... (RET).
void macro_flow(std::string_view raw, const std::string& s, bool romi, std::size_t line,
                std::vector<Frame>& frames) {
  std::string up;
  for (const char c : raw)
    up += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  if (romi) {
    if (up.find("(SUB") != std::string::npos) frames.push_back({"SUB", "", line});
    return;
  }
  if (s.find("WHILE") != std::string::npos) {
    frames.push_back({"WHILE", "", line});
  } else if (const auto at = s.find("END"); at != std::string::npos && !frames.empty() &&
                                            at + 3 < s.size() &&
                                            std::isdigit(static_cast<unsigned char>(s[at + 3]))) {
    frames.pop_back();
  }
}

std::string describe(const std::vector<Frame>& frames, std::string_view raw_first) {
  for (const Frame& f : frames) {
    if (f.kind == "SUB") return "";
    (void)raw_first;
  }
  if (frames.empty()) return "";
  const Frame& f = frames.back();
  const std::string what = f.kind == "IF"                         ? "an O-word if"
                           : f.kind == "WHILE" && f.label.empty() ? "a WHILE ... DO loop"
                                                                  : "an O-word " + f.kind;
  return what + " (opened at line " + std::to_string(f.line) + ")";
}

bool ends_program(const ScanLine& l) {
  for (const int m : l.m)
    if (m == 2 || m == 30) return true;
  return false;
}

// The sequence number a line starts with ("N10 #1=#1+1" too, which the
// word scan leaves alone as a macro line).
std::optional<long> leading_n(std::string_view raw) {
  std::size_t i = 0;
  while (i < raw.size() && (raw[i] == ' ' || raw[i] == '\t' || raw[i] == '/'))
    ++i;
  if (i >= raw.size() || (raw[i] != 'N' && raw[i] != 'n')) return std::nullopt;
  const std::string rest(raw.substr(i + 1, 12));
  std::size_t j = 0;
  const auto v = number_at(rest, j);
  if (!v || j == 0) return std::nullopt;
  return std::lround(*v);
}

// The jumps of a line: fanuc "GOTO 10", "IF [...] GOTO 10", "GOTO #1"
// (outside comments; ';' ends a block, not the line); romi "(GOTO N10)",
// "(IF P1 LT 3 GOTO N10)" (its statements are in parentheses; ';' starts a
// comment). Each target, -1 for one computed as it runs.
std::vector<long> goto_targets(std::string_view raw, bool romi) {
  std::string up;
  int paren = 0;
  for (const char c : raw) {
    if (romi && c == ';') break;
    if (!romi && (c == '(' || paren > 0)) {
      paren += c == '(' ? 1 : (c == ')' ? -1 : 0);
      continue;
    }
    up += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  }
  std::vector<long> targets;
  for (auto at = up.find("GOTO"); at != std::string::npos; at = up.find("GOTO", at + 4)) {
    std::size_t i = at + 4;
    while (i < up.size() && up[i] == ' ')
      ++i;
    if (i < up.size() && up[i] == 'N') ++i;
    const bool literal = i < up.size() && std::isdigit(static_cast<unsigned char>(up[i]));
    const auto v = literal ? number_at(up, i) : std::nullopt;
    targets.push_back(v ? std::lround(*v) : -1L);
  }
  return targets;
}

// Marks runs of lines with the reason a start there is refused, each line
// once (the first reason found stays): the next line not yet marked is
// found by path-halving links, so any number of jumps over any span costs
// little more than the lines (a hostile upload cannot make it quadratic).
class Marker {
 public:
  explicit Marker(std::vector<ScanLine>& lines) : lines_(lines), next_(lines.size() + 1) {
    for (std::size_t k = 0; k < next_.size(); ++k)
      next_[k] = k < lines.size() && taken(lines[k]) ? k + 1 : k;
  }

  void mark(std::size_t from, std::size_t to, const std::string& why) {
    for (std::size_t k = unmarked(from); k <= to && k < lines_.size(); k = unmarked(k + 1)) {
      lines_[k].inside = why;
      next_[k] = k + 1;
    }
  }

 private:
  static bool taken(const ScanLine& l) { return !l.inside.empty() || l.in_sub || l.past_end; }

  std::size_t unmarked(std::size_t k) {
    while (next_[k] != k) {
      next_[k] = next_[next_[k]];
      k = next_[k];
    }
    return k;
  }

  std::vector<ScanLine>& lines_;
  std::vector<std::size_t> next_;  // k itself when line k is unmarked
};

// Where each block number stands: its first and last line.
struct NumberedLines {
  std::size_t first = 0;
  std::size_t last = 0;
};

using LinesByNumber = std::unordered_map<long, NumberedLines>;

// romi: "(RPT N10,N50,2)" runs N10 to N50 again; a start inside that
// section would leave the repeat count behind.
void mark_repeats(const std::vector<ScanLine>& lines, const LinesByNumber& where, Marker& marker) {
  for (std::size_t i = 0; i < lines.size(); ++i) {
    std::string up;
    for (const char c : lines[i].raw)
      up += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    const auto rpt = up.find("RPT");
    if (rpt == std::string::npos) continue;
    std::vector<long> ns;
    for (std::size_t k = up.find('N', rpt); k != std::string::npos && ns.size() < 2;
         k = up.find('N', k + 1)) {
      std::size_t j = k + 1;
      if (auto v = number_at(up, j)) ns.push_back(std::lround(*v));
    }
    if (ns.size() < 2) continue;
    const auto a = where.find(ns[0]), b = where.find(ns[1]);
    if (a == where.end() || b == where.end()) continue;
    marker.mark(a->second.first, b->second.first,
                "the section repeated by the RPT at line " + std::to_string(i + 1));
  }
}

// fanuc and romi GOTO: the blocks between a jump back and its target run
// again (a loop whose count lives in a variable), the blocks a jump forward
// passes over may not run at all; a jump to a computed block number may go
// anywhere. A start there cannot be restored from the text.
void mark_jumps(const std::vector<ScanLine>& lines, const LinesByNumber& where, bool romi,
                Marker& marker) {
  for (std::size_t j = 0; j < lines.size(); ++j) {
    if (lines[j].in_sub || lines[j].past_end) continue;
    const std::string at = std::to_string(j + 1);
    for (const long target : goto_targets(lines[j].raw, romi)) {
      if (target < 0) {
        marker.mark(
            0, lines.size() - 1,
            "the reach of the GOTO at line " + at + ", to a block number computed as it runs");
        continue;
      }
      const auto found = where.find(target);
      if (found == where.end()) continue;  // the run stops there with an error
      const NumberedLines& t = found->second;
      if (t.first <= j) marker.mark(t.first, j, "the loop the GOTO at line " + at + " closes");
      if (t.last > j + 1) {
        marker.mark(j + 1, t.last - 1, "the blocks the GOTO at line " + at + " jumps over");
      }
    }
  }
}

// The loops and jumps of fanuc's and romi's statements, after the scan.
void mark_flow(std::vector<ScanLine>& lines, bool romi) {
  LinesByNumber where;
  for (std::size_t t = 0; t < lines.size(); ++t) {
    const auto n = lines[t].n ? lines[t].n : leading_n(lines[t].raw);
    if (!n) continue;
    const auto [it, added] = where.try_emplace(*n, NumberedLines{t, t});
    it->second.last = t;
  }
  Marker marker(lines);
  if (romi) mark_repeats(lines, where, marker);
  mark_jumps(lines, where, romi, marker);
}

}  // namespace

std::vector<ScanLine> scan_program(std::string_view text, std::string_view dialect) {
  const bool romi = dialect == "romi";
  const bool fanuc = dialect == "fanuc";
  std::vector<ScanLine> lines;
  std::vector<Frame> frames;
  bool ended = false, seen_block = false;
  for (std::size_t at = 0; at < text.size();) {
    std::size_t nl = text.find('\n', at);
    if (nl == std::string_view::npos) nl = text.size();
    ScanLine l;
    l.offset = at;
    l.raw = text.substr(at, nl - at);
    at = nl + 1;
    const std::size_t number = lines.size() + 1;
    const std::string s = stripped(l.raw, romi);
    const std::size_t depth_before = frames.size();
    const bool top_sub = !frames.empty() && frames.back().kind == "SUB";
    if (fanuc || romi) {
      macro_flow(l.raw, s, romi, number, frames);
    } else {
      o_word(s, number, frames);
    }
    if (!(fanuc && is_macro_line(s))) read_words(s, l.raw, romi, l);
    const bool opened = frames.size() > depth_before;
    const auto& scope = opened ? std::vector<Frame>(frames.begin(), frames.end() - 1) : frames;
    l.in_sub = false;
    for (const Frame& f : frames)
      if (f.kind == "SUB") l.in_sub = true;
    if (frames.size() < depth_before && top_sub) l.in_sub = true;  // its ENDSUB
    l.inside = describe(scope, l.raw);
    if (romi && l.in_sub && l.raw.find("RET") != std::string_view::npos) frames.pop_back();
    const std::string t = trim(l.raw);
    if (t == "%" && seen_block && !fanuc) ended = true;
    l.past_end = ended;
    if (!t.empty() && t != "%") seen_block = true;
    if (!l.in_sub && frames.empty() && ends_program(l)) ended = true;
    if (fanuc && t == "%" && seen_block) ended = true;
    lines.push_back(std::move(l));
  }
  if (romi || fanuc) mark_flow(lines, romi);
  return lines;
}

}  // namespace usina::gcode
