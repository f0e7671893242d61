#include "apt/cl_statement.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "apt/cl_text.hpp"

namespace usina::apt {
namespace {

// A piece of a statement: the part of one line it was joined from.
struct Piece {
  std::size_t at = 0;  // where it starts in the joined text
  std::uint32_t line = 0;
  std::uint64_t line_offset = 0;
  std::uint32_t col = 1;  // the column of its first character
};

char upper(char c) {
  return static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
}

bool blank(char c) {
  return c == ' ' || c == '\t';
}

// The line without its "$$" comment (a quoted text keeps its '$').
std::string_view uncommented(std::string_view line) {
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    if (line[i] == '\'') quoted = !quoted;
    if (!quoted && line[i] == '$' && i + 1 < line.size() && line[i + 1] == '$')
      return line.substr(0, i);
  }
  return line;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && blank(s.front()))
    s.remove_prefix(1);
  while (!s.empty() && (blank(s.back()) || s.back() == '\r'))
    s.remove_suffix(1);
  return s;
}

// Their text is read as written, not as arguments.
bool is_text_statement(std::string_view major) {
  return major == "PARTNO" || major == "PPRINT" || major == "INSERT" || major == "REMARK" ||
         major == "TOOL PATH";
}

class Builder {
 public:
  Builder(std::uint32_t file, core::DiagnosticSink& diags) : file_(file), diags_(diags) {}

  // Adds a line's text; false once the statement is too long (reported).
  void add(std::string_view part, std::uint32_t line, std::uint64_t offset, std::uint32_t col);

  bool empty() const { return text_.empty() && !too_long_; }

  // The statement, or nothing when it is blank or was reported.
  std::optional<ClStatement> take();

 private:
  core::SourceLoc loc_at(std::size_t i) const;
  bool parse_args(ClStatement& st, std::size_t from);
  bool parse_arg(ClStatement& st, std::size_t from, std::size_t to);

  bool fail(core::Code code, std::size_t at, const std::string& why) {
    diags_.report(core::Diagnostic{code, core::Severity::Error, loc_at(at), why});
    return false;
  }

  std::uint32_t file_;
  core::DiagnosticSink& diags_;
  std::string text_;
  std::vector<Piece> pieces_;
  bool too_long_ = false;
};

void Builder::add(std::string_view part, std::uint32_t line, std::uint64_t offset,
                  std::uint32_t col) {
  if (too_long_) return;
  if (text_.size() + part.size() > kMostClStatementBytes) {
    pieces_.push_back(Piece{text_.size(), line, offset, col});
    fail(core::Code::ClTooLarge, text_.size(),
         fmt::format("the statement is longer than {} bytes", kMostClStatementBytes));
    too_long_ = true;
    return;
  }
  pieces_.push_back(Piece{text_.size(), line, offset, col});
  text_ += part;
}

core::SourceLoc Builder::loc_at(std::size_t i) const {
  std::size_t k = 0;
  while (k + 1 < pieces_.size() && pieces_[k + 1].at <= i)
    ++k;
  const Piece& p = pieces_.empty() ? Piece{} : pieces_[k];
  return core::SourceLoc{file_, p.line, static_cast<std::uint32_t>(p.col + (i - p.at)), 1,
                         p.line_offset};
}

std::optional<ClStatement> Builder::take() {
  std::optional<ClStatement> out;
  if (!too_long_ && !trim(text_).empty()) {
    ClStatement st;
    std::size_t i = 0;
    while (i < text_.size() && blank(text_[i]))
      ++i;
    st.loc = loc_at(i);
    const std::size_t slash = text_.find('/');
    std::size_t end = slash == std::string::npos ? text_.size() : slash;
    // PARTNO and its like may put their text after a blank, with no '/'.
    if (slash == std::string::npos) {
      const std::size_t gap = text_.find_first_of(" \t", i);
      if (gap != std::string::npos) end = gap;
    }
    for (const char c : trim(std::string_view(text_).substr(i, end - i))) {
      if (blank(c) && (st.major.empty() || st.major.back() == ' ')) continue;
      st.major.push_back(blank(c) ? ' ' : upper(c));
    }
    const std::size_t from = end < text_.size() ? end + 1 : end;
    st.rest = std::string(trim(std::string_view(text_).substr(from)));
    if (is_text_statement(st.major) || parse_args(st, from)) out = std::move(st);
  }
  text_.clear();
  pieces_.clear();
  too_long_ = false;
  return out;
}

bool Builder::parse_args(ClStatement& st, std::size_t from) {
  bool quoted = false;
  std::size_t start = from;
  for (std::size_t i = from; i <= text_.size(); ++i) {
    if (i < text_.size() && text_[i] == '\'') quoted = !quoted;
    if (i < text_.size() && (quoted || text_[i] != ',')) continue;
    if (!parse_arg(st, start, i)) return false;
    start = i + 1;
    if (st.args.size() > kMostClArguments)
      return fail(core::Code::ClTooLarge, i,
                  fmt::format("more than {} arguments", kMostClArguments));
  }
  return true;
}

bool Builder::parse_arg(ClStatement& st, std::size_t from, std::size_t to) {
  while (from < to && blank(text_[from]))
    ++from;
  while (to > from && (blank(text_[to - 1]) || text_[to - 1] == '\r'))
    --to;
  if (from == to) return true;  // ",," and a trailing ','
  const std::string_view s = std::string_view(text_).substr(from, to - from);
  ClArg a;
  a.loc = loc_at(from);
  a.loc.length = static_cast<std::uint32_t>(s.size());
  if (s.front() == '\'') {
    a.kind = ClArg::Kind::Text;
    a.text =
        std::string(s.substr(1, s.size() >= 2 && s.back() == '\'' ? s.size() - 2 : s.size() - 1));
    st.args.push_back(std::move(a));
    return true;
  }
  const std::size_t sign = s.front() == '+' || s.front() == '-' ? 1 : 0;
  const bool numeric =
      sign < s.size() && (std::isdigit(static_cast<unsigned char>(s[sign])) != 0 || s[sign] == '.');
  if (numeric) {
    double v = 0.0;
    const char* first = s.data() + (s.front() == '+' ? 1 : 0);
    const auto [end, ec] = std::from_chars(first, s.data() + s.size(), v);
    if (ec == std::errc() && end == s.data() + s.size()) {
      if (!std::isfinite(v) || std::fabs(v) > kLargestClNumber)
        return fail(core::Code::ClTooLarge, from,
                    fmt::format("the number {} is beyond {:g}", s, kLargestClNumber));
      a.value = std::fabs(v) < 1e-150 ? 0.0 : v;  // no subnormal residue
      st.args.push_back(std::move(a));
      return true;
    }
    if (ec == std::errc::result_out_of_range)
      return fail(core::Code::ClTooLarge, from, fmt::format("the number {} is out of range", s));
  }
  a.kind = ClArg::Kind::Word;
  for (const char c : s)
    a.text.push_back(upper(c));
  st.args.push_back(std::move(a));
  return true;
}

}  // namespace

void for_each_cl_statement(std::string_view text, std::uint32_t file, core::DiagnosticSink& diags,
                           const std::function<bool(const ClStatement&)>& take) {
  Builder b(file, diags);
  std::size_t at = 0;
  std::uint32_t line = 0;
  while (at < text.size()) {
    std::size_t end = text.find('\n', at);
    if (end == std::string_view::npos) end = text.size();
    ++line;
    std::string_view body = uncommented(text.substr(at, end - at));
    while (!body.empty() && (blank(body.back()) || body.back() == '\r'))
      body.remove_suffix(1);
    // One '$' at the end continues the statement on the next line.
    const bool more = !body.empty() && body.back() == '$';
    if (more) body.remove_suffix(1);
    b.add(body, line, at, 1);
    if (!more) {
      if (auto st = b.take(); st && !take(*st)) return;
    }
    at = end + 1;
  }
  if (auto st = b.take(); st) take(*st);
}

}  // namespace usina::apt
