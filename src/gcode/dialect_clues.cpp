#include "gcode/dialect_clues.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <set>

#include <fmt/format.h>

namespace usina::gcode {
namespace {

char upper(char c) {
  return static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
}

char lower(char c) {
  return static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
}

bool is_alnum(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0;
}

std::string_view trim(std::string_view s) {
  const std::size_t a = s.find_first_not_of(" \t\r");
  if (a == std::string_view::npos) return {};
  return s.substr(a, s.find_last_not_of(" \t\r") - a + 1);
}

// Splits a line into code and comments: '(' ... ')' (nested, as Fanuc and
// LinuxCNC read them) and ';' to the end of the line.
HeadLine split_line(std::string_view line) {
  HeadLine out;
  int depth = 0;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (depth == 0 && c == ';') {
      const std::string_view rest = trim(line.substr(i + 1));
      out.semicolon_text = !rest.empty();
      out.bare_semicolon = rest.empty();
      for (char r : rest)
        out.comments += lower(r);
      break;
    }
    if (c == '(') {
      if (depth++ == 0) continue;
    } else if (c == ')' && depth > 0) {
      if (--depth == 0) {
        out.comments += ' ';
        continue;
      }
    }
    if (depth > 0) {
      out.comments += lower(c);
    } else if (c != '\r') {
      out.code += upper(c);
    }
  }
  out.code = std::string(trim(out.code));
  return out;
}

// The words of a line of code whose letter is in `letters`, as (letter,
// value) pairs; a letter without a plain number after it is skipped.
std::vector<std::pair<char, double>> words_of(std::string_view code) {
  std::vector<std::pair<char, double>> out;
  for (std::size_t i = 0; i < code.size(); ++i) {
    if (!std::isalpha(static_cast<unsigned char>(code[i]))) continue;
    std::size_t j = i + 1;
    while (j < code.size() && code[j] == ' ')
      ++j;
    std::string number;
    while (j < code.size() && (std::isdigit(static_cast<unsigned char>(code[j])) ||
                               code[j] == '.' || code[j] == '-' || code[j] == '+')) {
      number += code[j++];
    }
    char* end = nullptr;
    const double v = std::strtod(number.c_str(), &end);
    if (!number.empty() && end != number.c_str() && std::isfinite(v)) out.emplace_back(code[i], v);
  }
  return out;
}

bool is_code(double v, double code) {
  return std::fabs(v - code) < 1e-6;
}

}  // namespace

std::vector<HeadLine> read_head(std::string_view text) {
  std::vector<HeadLine> lines;
  for (std::size_t start = 0; start <= text.size() && lines.size() < kHeadLines;) {
    const std::size_t nl = text.find('\n', start);
    const std::size_t end = nl == std::string_view::npos ? text.size() : nl;
    lines.push_back(split_line(text.substr(start, end - start)));
    if (nl == std::string_view::npos) break;
    start = nl + 1;
  }
  return lines;
}

bool ends_with_program_end(std::string_view text) {
  // The last three blocks with code, within the last 4 KB (a program end
  // is a short block; a file of one huge line has none to find).
  constexpr std::size_t kTailBytes = 4096;
  constexpr int kBlocksLooked = 3;
  if (text.size() > kTailBytes) text = text.substr(text.size() - kTailBytes);
  int looked = 0;
  std::size_t end = text.size();
  while (looked < kBlocksLooked && end > 0) {
    const std::size_t nl = end > 0 ? text.rfind('\n', end - 1) : std::string_view::npos;
    const std::size_t start = nl == std::string_view::npos ? 0 : nl + 1;
    const HeadLine line = split_line(text.substr(start, end - start));
    end = nl == std::string_view::npos ? 0 : nl;
    if (line.code.empty()) continue;
    ++looked;
    if (line.code == "%") return true;
    for (const auto& [letter, value] : words_of(line.code))
      if (letter == 'M' && (is_code(value, 2) || is_code(value, 30))) return true;
  }
  return false;
}

namespace {

// Weights: a named control or LinuxCNC's own extension outweighs any one
// habit; a habit outweighs an extension that many controls share.
constexpr int kNamedControl = 6;
constexpr int kNgcExtension = 4;
constexpr int kProgramNumber = 4;
constexpr int kFanucBlockEnd = 3;
constexpr int kNoProgramEnd = 3;
constexpr int kCodeGrblLacks = 2;  // a kind of code; two kinds at most count
constexpr int kToolWithoutChange = 2;
constexpr int kTapExtension = 2;
constexpr int kGcodeExtension = 1;

bool names_word(std::string_view text, std::string_view word) {
  for (std::size_t at = text.find(word); at != std::string_view::npos;
       at = text.find(word, at + 1)) {
    const std::size_t after = at + word.size();
    if ((at == 0 || !is_alnum(text[at - 1])) && (after == text.size() || !is_alnum(text[after])))
      return true;
  }
  return false;
}

// Comments that name a control, its maker or a machine built on it (CAM
// posts write their target in the header: "(Image2Gcode for Grbl)").
void control_named(const std::vector<HeadLine>& head, std::vector<Clue>& out) {
  struct Name {
    std::string_view word;
    std::string_view dialect;
  };

  static constexpr std::array<Name, 12> kNames{{{"grbl", "grbl"},
                                                {"grblhal", "grbl"},
                                                {"fluidnc", "grbl"},
                                                {"shapeoko", "grbl"},
                                                {"x-carve", "grbl"},
                                                {"linuxcnc", "rs274ngc"},
                                                {"emc2", "rs274ngc"},
                                                {"pathpilot", "rs274ngc"},
                                                {"mach3", "rs274ngc"},
                                                {"mach4", "rs274ngc"},
                                                {"fanuc", "fanuc"},
                                                {"haas", "fanuc"}}};
  std::set<std::string_view> named;
  for (const HeadLine& line : head) {
    if (line.comments.empty()) continue;
    for (const Name& n : kNames) {
      if (named.count(n.dialect) != 0 || !names_word(line.comments, n.word)) continue;
      named.insert(n.dialect);
      out.push_back({n.dialect, kNamedControl, fmt::format("a comment names '{}'", n.word)});
    }
  }
}

// Fanuc's program number opens the program (O1234); a ';' comment rules
// it out, since Fanuc reads ';' as the end of a block.
void fanuc_habits(const std::vector<HeadLine>& head, std::vector<Clue>& out) {
  std::size_t code_lines = 0;
  std::size_t bare = 0;
  bool semicolon_text = false;
  const HeadLine* first = nullptr;
  for (const HeadLine& line : head) {
    semicolon_text = semicolon_text || line.semicolon_text;
    if (line.code.empty() || line.code == "%") continue;
    if (first == nullptr) first = &line;
    ++code_lines;
    if (line.bare_semicolon) ++bare;
  }
  if (semicolon_text) return;
  if (first != nullptr && first->code.size() > 1 && first->code[0] == 'O' &&
      std::all_of(first->code.begin() + 1, first->code.end(),
                  [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; })) {
    out.push_back(
        {"fanuc", kProgramNumber, fmt::format("the program number '{}' opens it", first->code)});
  }
  if (bare >= 3 && 2 * bare >= code_lines)
    out.push_back({"fanuc", kFanucBlockEnd, "';' ends its blocks (Fanuc's end of block)"});
}

// The kinds of code Grbl 1.1 refuses (gnea/grbl gcode.c) that LinuxCNC runs.
std::set<std::string> kinds_grbl_lacks(const HeadLine& line) {
  std::set<std::string> kinds;
  if (line.code.find('[') != std::string::npos) kinds.insert("expressions");
  for (std::size_t at = line.code.find('#'); at != std::string::npos;
       at = line.code.find('#', at + 1)) {
    if (at + 1 < line.code.size() && std::isdigit(static_cast<unsigned char>(line.code[at + 1])))
      kinds.insert("parameters");
  }
  for (const auto& [letter, v] : words_of(line.code)) {
    const long tenths = std::lround(v * 10);
    if (letter == 'M' && tenths == 60) kinds.insert("M6");
    if (letter == 'M' && tenths >= 620 && tenths <= 680) kinds.insert("M62-M68");
    if (letter == 'G' && tenths == 430) kinds.insert("G43");
    if (letter == 'G' && (tenths == 410 || tenths == 420)) kinds.insert("G41/G42");
    if (letter == 'G' && (tenths == 640 || tenths == 611)) kinds.insert("G64");
    if (letter == 'G' && (tenths == 730 || tenths == 760 || (tenths >= 810 && tenths <= 890)))
      kinds.insert("canned cycles");
  }
  return kinds;
}

// What a program's codes say: codes Grbl refuses lean to LinuxCNC; a tool
// named (T1) but never changed (no M6) is how Grbl posts write it, since
// Grbl has no tool changer.
void code_habits(const std::vector<HeadLine>& head, std::vector<Clue>& out) {
  std::set<std::string> lacks;
  bool tool = false;
  for (const HeadLine& line : head) {
    lacks.merge(kinds_grbl_lacks(line));
    for (const auto& [letter, v] : words_of(line.code))
      tool = tool || letter == 'T';
  }
  if (!lacks.empty()) {
    std::string kinds;
    for (const std::string& k : lacks)
      kinds += (kinds.empty() ? "" : ", ") + k;
    const int n = static_cast<int>(std::min<std::size_t>(lacks.size(), 2));
    out.push_back({"rs274ngc", kCodeGrblLacks * n, fmt::format("codes Grbl refuses ({})", kinds)});
  }
  if (tool && lacks.count("M6") == 0)
    out.push_back({"grbl", kToolWithoutChange, "a T word and no M6 (Grbl changes no tools)"});
}

std::string extension_of(std::string_view file_name) {
  const std::size_t slash = file_name.find_last_of("/\\");
  const std::string_view base =
      slash == std::string_view::npos ? file_name : file_name.substr(slash + 1);
  const std::size_t dot = base.rfind('.');
  std::string ext;
  if (dot == std::string_view::npos || dot == 0) return ext;
  for (char c : base.substr(dot + 1))
    ext += lower(c);
  return ext;
}

// The extension: .ngc is LinuxCNC's own, .tap the usual one of Mach3 and
// of LinuxCNC posts, .gcode that of hobby machines and their senders; .nc
// is every control's and says nothing.
void extension_hint(std::string_view file_name, std::vector<Clue>& out) {
  const std::string ext = extension_of(file_name);
  if (ext == "ngc") out.push_back({"rs274ngc", kNgcExtension, "the extension '.ngc'"});
  if (ext == "tap") out.push_back({"rs274ngc", kTapExtension, "the extension '.tap'"});
  if (ext == "gcode") out.push_back({"grbl", kGcodeExtension, "the extension '.gcode'"});
}

}  // namespace

std::vector<Clue> weigh_clues(const std::vector<HeadLine>& head, std::string_view text,
                              std::string_view file_name) {
  std::vector<Clue> clues;
  control_named(head, clues);
  fanuc_habits(head, clues);
  code_habits(head, clues);
  // LinuxCNC refuses a program without M2, M30 or a closing '%' (after
  // running it); a Grbl stream needs no end. An empty text is no program.
  const bool any_code =
      std::any_of(head.begin(), head.end(), [](const HeadLine& l) { return !l.code.empty(); });
  if (any_code && !ends_with_program_end(text))
    clues.push_back({"grbl", kNoProgramEnd, "no M2, M30 or '%' at its end"});
  extension_hint(file_name, clues);
  return clues;
}

}  // namespace usina::gcode
