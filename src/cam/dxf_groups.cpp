#include "cam/dxf_groups.hpp"

#include <algorithm>
#include <array>
#include <iterator>
#include <limits>
#include <vector>

#include <fmt/format.h>

namespace usina::cam {
namespace {

// At most 40 characters of `s` for a message, bytes outside printable ASCII
// as \xNN so that no control character reaches the terminal.
std::string shown(std::string_view s) {
  std::string out;
  for (std::size_t i = 0; i < s.size() && i < 40; ++i) {
    const auto c = static_cast<unsigned char>(s[i]);
    out +=
        c >= 0x20 && c < 0x7f ? std::string(1, static_cast<char>(c)) : fmt::format("\\x{:02x}", c);
  }
  return s.size() > 40 ? out + "..." : out;
}

std::string_view trimmed(std::string_view s) {
  const std::size_t first = s.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

// A decimal integer of at most 18 digits, blanks around it allowed.
std::optional<long long> integer(std::string_view s) {
  s = trimmed(s);
  const bool minus = !s.empty() && s.front() == '-';
  if (!s.empty() && (s.front() == '-' || s.front() == '+')) s.remove_prefix(1);
  if (s.empty() || s.size() > 18) return std::nullopt;
  long long v = 0;
  for (const char c : s) {
    if (c < '0' || c > '9') return std::nullopt;
    v = v * 10 + (c - '0');
  }
  return minus ? -v : v;
}

// Group codes are 0 to 1071 in the DXF reference, negative ones are the
// API's; a few more digits are harmless to dxflib and keep odd writers read.
constexpr long long kMinGroupCode = -9999;
constexpr long long kMaxGroupCode = 9999;

// The lines of the file, numbered from 1. A line ends at LF (CRs before it
// are dropped, as dxflib drops them); a file without any LF is split at CR
// (old Mac line ends).
class Lines {
 public:
  explicit Lines(std::string_view text)
      : text_(text), eol_(text.find('\n') != std::string_view::npos ? '\n' : '\r') {}

  bool next(std::string_view& line) {
    if (pos_ >= text_.size()) return false;
    std::size_t end = text_.find(eol_, pos_);
    if (end == std::string_view::npos) end = text_.size();
    line = text_.substr(pos_, end - pos_);
    while (!line.empty() && line.back() == '\r')
      line.remove_suffix(1);
    pos_ = end + 1;
    ++number_;
    return true;
  }

  std::size_t number() const { return number_; }

 private:
  std::string_view text_;
  char eol_;
  std::size_t pos_ = 0;
  std::size_t number_ = 0;
};

// A count group of an object and the groups it counts. dxflib allocates the
// count's worth of items when it meets the count and drops items that come
// before it; `followers` are the item's other coordinates, which dxflib
// writes at the index of the last item (before the first one: out of bounds
// for a bulge). `optional` items may be left out altogether (SPLINE weights).
struct CountRule {
  std::string_view kind;
  int count_code;
  int item_code;
  std::array<int, 3> followers;
  const char* items;
  bool optional = false;
};

constexpr int kNone = -1000;

constexpr std::array<CountRule, 6> kCountRules{{
    {"LWPOLYLINE", 90, 10, {20, 30, 42}, "vertices"},
    {"SPLINE", 72, 40, {kNone, kNone, kNone}, "knots"},
    {"SPLINE", 73, 10, {20, 30, kNone}, "control points"},
    {"SPLINE", 73, 41, {kNone, kNone, kNone}, "weights", true},
    {"SPLINE", 74, 11, {21, 31, kNone}, "fit points"},
    {"LEADER", 76, 10, {20, 30, kNone}, "vertices"},
}};

// The counts of the object being read (from its 0 or 9 group to the next
// one: dxflib starts an object at either) against its items.
class ObjectCheck {
 public:
  void begin(std::string_view kind, std::size_t line) {
    kind_ = kind;
    line_ = line;
    state_ = {};
  }

  // The count groups an object of this kind gets before its own groups: a
  // count of 0 resets dxflib's arrays, which otherwise carry the previous
  // object's items into one that declares no count.
  std::string reset_counts() const {
    std::string out;
    for (const CountRule& r : kCountRules) {
      if (r.kind == kind_ && !r.optional) out += fmt::format("{}\n0\n", r.count_code);
    }
    return out;
  }

  // An error message for the group, or empty.
  std::string group(int code, std::string_view value) {
    for (std::size_t i = 0; i < kCountRules.size(); ++i) {
      const CountRule& r = kCountRules[i];
      if (r.kind != kind_) continue;
      if (auto e = count_or_item(r, state_[i], code, value); !e.empty()) return e;
    }
    return {};
  }

  std::size_t line() const { return line_; }

  // An error message when a count does not match its items, or empty.
  std::string end() const {
    for (std::size_t i = 0; i < kCountRules.size(); ++i) {
      const CountRule& r = kCountRules[i];
      const State& s = state_[i];
      if (r.kind != kind_ || s.items == s.declared || (r.optional && s.items == 0)) continue;
      return fmt::format("the {} declares {} {} (group {}) but lists {} (group {})", kind_,
                         s.declared, r.items, r.count_code, s.items, r.item_code);
    }
    return {};
  }

 private:
  struct State {
    bool counted = false;
    int declared = 0;
    int items = 0;
  };

  std::string count_or_item(const CountRule& r, State& s, int code, std::string_view value) const {
    if (code == r.count_code) {
      const std::optional<long long> n = integer(value);
      if (!n || *n < 0 || *n > std::numeric_limits<int>::max()) {
        return fmt::format(
            "the {}'s count of {} (group {}) is \"{}\", not a whole number from 0 "
            "to {}",
            kind_, r.items, code, shown(value), std::numeric_limits<int>::max());
      }
      if (s.counted) return fmt::format("the {} has a second group {}", kind_, code);
      if (s.items > 0) {
        return fmt::format("the {}'s count of {} (group {}) comes after {} of them", kind_, r.items,
                           code, s.items);
      }
      s = {true, static_cast<int>(*n), 0};
    } else if (code == r.item_code) {
      ++s.items;
    } else if (s.items == 0 &&
               std::find(r.followers.begin(), r.followers.end(), code) != r.followers.end()) {
      return fmt::format("the {} has a group {} before its first group {}", kind_, code,
                         r.item_code);
    }
    return {};
  }

  std::string_view kind_;
  std::size_t line_ = 0;
  std::array<State, kCountRules.size()> state_{};
};

void report(core::DiagnosticSink& diags, core::Code code, const std::string& name, std::size_t line,
            const std::string& message) {
  diags.report({code, core::Severity::Error, {}, fmt::format("{}:{}: {}", name, line, message)});
}

// E_DXF_UNREADABLE when the bytes are not text (checked before any line, so
// the message says what the file is rather than which line looks wrong).
bool is_text(std::string_view bytes, const std::string& name, core::DiagnosticSink& diags) {
  if (bytes.starts_with("AutoCAD Binary DXF")) {
    report(diags, core::Code::DxfUnreadable, name, 1,
           "a binary DXF; usina reads ASCII DXF: save the drawing as ASCII DXF");
    return false;
  }
  const std::size_t nul = bytes.find('\0');
  if (nul == std::string_view::npos) return true;
  const auto line = 1 + static_cast<std::size_t>(std::count(
                            bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(nul), '\n'));
  report(diags, core::Code::DxfUnreadable, name, line,
         "a NUL byte: not a text file, so not an ASCII DXF drawing");
  return false;
}

// Reads the groups of `text` into `out`; false after reporting the first
// malformed line.
class GroupReader {
 public:
  GroupReader(std::string_view text, const std::string& name, core::DiagnosticSink& diags)
      : lines_(text), name_(name), diags_(diags) {}

  bool read(std::string& out) {
    std::string_view code_line;
    while (lines_.next(code_line)) {
      const std::size_t at = lines_.number();
      const std::optional<long long> parsed = integer(code_line);
      if (!parsed || *parsed < kMinGroupCode || *parsed > kMaxGroupCode) {
        return fail(at,
                    fmt::format("\"{}\" is not a group code (a whole number, -9999 to 9999); the "
                                "lines of a DXF file alternate between a group code and its value",
                                shown(code_line)));
      }
      const auto code = static_cast<int>(*parsed);
      std::string_view value;
      if (!lines_.next(value)) {
        return fail(at, fmt::format("group {} has no value line: the file is cut short", code));
      }
      if (code == 999) continue;  // a comment: not needed, and dxflib mis-reads some
      if (!take(code, value, out)) return false;
      if ((code == 0) && value == "EOF") return close_object();
    }
    if (!close_object()) return false;
    return fail(lines_.number(),
                "the file ends without the group 0 EOF that ends a DXF file: it may be cut short");
  }

 private:
  bool take(int code, std::string_view value, std::string& out) {
    if (value.size() > kMaxDxfLineLength) {
      return fail(lines_.number(),
                  fmt::format("a value of {} characters; usina reads DXF lines of up to {} "
                              "characters (AutoCAD writes at most 2,049)",
                              value.size(), kMaxDxfLineLength));
    }
    if (code == 9 && !value.starts_with('$')) {
      // dxflib would start an object named by the value: "LINE" would be a line.
      return fail(lines_.number(), fmt::format("a header variable named \"{}\"; their names (group "
                                               "9) start with $",
                                               shown(value)));
    }
    if (code == 0 || code == 9) {
      if (!close_object()) return false;
      object_.begin(value, lines_.number() - 1);
    } else if (const std::string e = object_.group(code, value); !e.empty()) {
      return fail(lines_.number() - 1, e);
    }
    fmt::format_to(std::back_inserter(out), "{}\n", code);
    out.append(value);
    out += '\n';
    if (code == 0 || code == 9) out += object_.reset_counts();
    return true;
  }

  bool close_object() {
    const std::string e = object_.end();
    return e.empty() || fail(object_.line(), e);
  }

  bool fail(std::size_t line, const std::string& message) {
    report(diags_, core::Code::DxfMalformed, name_, line, message);
    return false;
  }

  Lines lines_;
  const std::string& name_;
  core::DiagnosticSink& diags_;
  ObjectCheck object_;
};

}  // namespace

std::optional<std::string> canonical_dxf(std::string_view bytes, const std::string& name,
                                         core::DiagnosticSink& diags) {
  if (!is_text(bytes, name, diags)) return std::nullopt;
  if (bytes.starts_with("\xEF\xBB\xBF")) bytes.remove_prefix(3);  // a UTF-8 byte order mark
  if (bytes.find_first_not_of(" \t\r\n") == std::string_view::npos) {
    report(diags, core::Code::DxfUnreadable, name, 1, "the file is empty: not a DXF drawing");
    return std::nullopt;
  }
  std::string out;
  out.reserve(bytes.size() + bytes.size() / 8);
  GroupReader reader(bytes, name, diags);
  if (!reader.read(out)) return std::nullopt;
  return out;
}

}  // namespace usina::cam
