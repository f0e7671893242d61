#include "dnc/store_facts.hpp"

#include <algorithm>
#include <array>
#include <set>

#include <fmt/format.h>

#include "dnc/store_names.hpp"

namespace usina::dnc {
namespace {

// What a dialect's text looks like to the scan (gcode's LexicalRules and
// each reader's comment forms).
struct ScanRules {
  std::string_view block_ends;  // besides the newline
  bool semicolon_comment;       // ';' to the block end is a comment (not fanuc's end of block)
  bool named_parameters;        // '<name>' holds letters that are no words (rs274ngc, grbl)
  bool romi;                    // ( ) may hold a statement; lower case letters are other words
  bool fanuc;                   // O or ':' heads a block, words may follow it
};

ScanRules rules_of(std::string_view dialect) {
  if (dialect == "fanuc") return {";", false, false, false, true};
  if (dialect == "romi") return {"#", true, false, true, false};
  return {"", true, true, false, false};
}

bool is_letter(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
}

bool is_digit(char c) {
  return c >= '0' && c <= '9';
}

char lower(char c) {
  return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
}

// romi's parenthesised Fagor statements (gcode/romi/syntax.cpp): (P1 = ..),
// (IF .. GOTO ..), (GOTO ..), (RPT ..), (CALL ..), (SUB ..), (RET); any
// other text in parentheses is a comment.
bool romi_statement(std::string_view inside) {
  std::size_t i = 0;
  while (i < inside.size() && (inside[i] == ' ' || inside[i] == '\t'))
    ++i;
  std::string head;
  for (std::size_t k = i; k < inside.size() && head.size() < 4 && is_letter(inside[k]); ++k)
    head += static_cast<char>(lower(inside[k]));
  if (head.starts_with("p") && i + 1 < inside.size() && is_digit(inside[i + 1])) {
    std::size_t k = i + 1;
    while (k < inside.size() && (is_digit(inside[k]) || inside[k] == ' '))
      ++k;
    return k < inside.size() && inside[k] == '=';
  }
  constexpr std::array<std::string_view, 6> kKeywords = {"if", "goto", "rpt", "call", "sub", "ret"};
  return std::ranges::any_of(kKeywords,
                             [&](std::string_view word) { return head.starts_with(word); });
}

// One pass over the text, block by block.
class FactScan {
 public:
  FactScan(std::string_view text, ScanRules rules) : s_(text), rules_(rules) {}

  ProgramFacts run() {
    if (s_.starts_with("\xEF\xBB\xBF")) i_ = 3;  // a UTF-8 byte-order mark
    while (i_ < s_.size())
      block();
    out_.tools.assign(tools_.begin(), tools_.end());
    return std::move(out_);
  }

 private:
  bool block_end(char c) const {
    return c == '\n' || rules_.block_ends.find(c) != std::string_view::npos;
  }

  std::size_t end_of_block(std::size_t from) const {
    while (from < s_.size() && !block_end(s_[from]))
      ++from;
    return from;
  }

  void skip_blanks() {
    while (i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '\t' || s_[i_] == '\r'))
      ++i_;
  }

  void block() {
    program_number();
    char before = '\0';
    while (i_ < s_.size() && !block_end(s_[i_])) {
      const char c = s_[i_];
      if (c == '(') {
        parenthesis();
      } else if (c == ';' && rules_.semicolon_comment) {
        const std::size_t end = end_of_block(i_);
        comment(s_.substr(i_ + 1, end - i_ - 1));
        i_ = end;
      } else if (c == '<' && rules_.named_parameters) {
        while (i_ < s_.size() && s_[i_] != '>' && !block_end(s_[i_]))
          ++i_;
      } else if ((c == 'T' || (c == 't' && !rules_.romi)) && !is_letter(before)) {
        ++i_;
        tool_word();
        before = c;
        continue;
      } else {
        ++i_;
      }
      before = c;
    }
    if (i_ < s_.size()) ++i_;  // the block's end
  }

  // The digits at i_ (blanks between them, as the readers allow), consumed;
  // empty when none.
  std::string digits() {
    std::string out;
    while (i_ < s_.size() && (is_digit(s_[i_]) || s_[i_] == ' ' || s_[i_] == '\t')) {
      if (is_digit(s_[i_])) out += s_[i_];
      ++i_;
    }
    return out;
  }

  // fanuc: O1234 or :1234 heads a block (tape.cpp's read_block_head), words
  // may follow. rs274ngc, grbl: a bare O number, nothing but a comment after
  // it ("o100 sub" is a subroutine's label). romi: its O word is the tool's
  // offset register, no program number.
  void program_number() {
    skip_blanks();
    if (i_ < s_.size() && s_[i_] == '/') {
      ++i_;
      if (i_ < s_.size() && is_digit(s_[i_])) ++i_;
      skip_blanks();
    }
    if (rules_.romi || i_ >= s_.size()) return;
    const char c = s_[i_];
    if (c != 'O' && c != 'o' && !(c == ':' && rules_.fanuc)) return;
    const std::size_t at = i_;
    ++i_;
    const std::string number = digits();
    const bool bare = i_ >= s_.size() || block_end(s_[i_]) || s_[i_] == '(' || s_[i_] == ';';
    if (number.empty() || (!rules_.fanuc && !bare)) {
      i_ = at;
      return;
    }
    const std::string written = "o" + number;
    if (out_.o_numbers.size() >= kMaxProgramNumbers) return;
    for (const std::string& o : out_.o_numbers)
      if (o == written) return;
    out_.o_numbers.push_back(written);
  }

  // After a T: its whole number, kept; T#1, T[..] and T1.5 are not.
  void tool_word() {
    skip_blanks();
    const std::string number = digits();
    if (number.empty() || number.size() > 8) return;
    if (i_ < s_.size() && s_[i_] == '.') {
      ++i_;
      for (; i_ < s_.size() && is_digit(s_[i_]); ++i_)
        if (s_[i_] != '0') return;
    }
    if (tools_.size() < kMaxTools) tools_.insert(std::stoll(number));
  }

  // From the '(' at i_ to its ')': inner pairs belong to it (fanuc's
  // skip_comment); never closed, it ends with its line (fanuc) or block.
  void parenthesis() {
    const std::size_t open = i_;
    int depth = 0;
    for (; i_ < s_.size(); ++i_) {
      const char c = s_[i_];
      if (c == '\n' || (!rules_.fanuc && block_end(c))) break;
      if (c == '(') ++depth;
      if (c == ')' && --depth == 0) break;
    }
    const std::string_view inside = s_.substr(open + 1, i_ - open - 1);
    const bool closed = i_ < s_.size() && s_[i_] == ')';
    if (closed) ++i_;
    if (!(rules_.romi && closed && romi_statement(inside))) comment(inside);
  }

  // Keeps a comment's text: lower case, blanks at its ends trimmed, control
  // characters as blanks, bytes that are not UTF-8 as '?', within the bound.
  void comment(std::string_view text) {
    std::string& all = out_.comments;
    if (all.size() >= kMaxCommentBytes) return;
    std::string one;
    for (std::size_t k = 0; k < text.size();) {
      const std::size_t n = utf8_sequence_length(text, k);
      if (n == 0) {
        one += '?';
        ++k;
        continue;
      }
      const auto b = static_cast<unsigned char>(text[k]);
      if (n == 1) one += (b < 0x20 || b == 0x7f) ? ' ' : lower(text[k]);
      if (n > 1) one.append(text.substr(k, n));
      k += n;
    }
    const auto first = one.find_first_not_of(' ');
    if (first == std::string::npos) return;
    one = one.substr(first, one.find_last_not_of(' ') - first + 1);
    if (!all.empty()) all += '\n';
    for (std::size_t k = 0; k < one.size();) {
      const std::size_t n = utf8_sequence_length(one, k);
      if (all.size() + n > kMaxCommentBytes) return;
      all.append(one, k, n);
      k += n;
    }
  }

  std::string_view s_;
  ScanRules rules_;
  std::size_t i_ = 0;
  ProgramFacts out_;
  std::set<std::int64_t> tools_;
};

std::string joined(const std::vector<std::string>& words) {
  std::string out;
  for (const std::string& w : words)
    out += (out.empty() ? "" : " ") + w;
  return out;
}

StoreResult<void> record_facts_of(Database& db, std::int64_t revision, const ProgramFacts& f) {
  const std::string numbers = joined(f.o_numbers);
  auto made =
      db.query("INSERT INTO revision_facts (revision, o_numbers, comments) VALUES ($1, $2, $3)",
               {revision, std::string_view(numbers), std::string_view(f.comments)});
  if (!made) return tl::unexpected(made.error());
  if (f.tools.empty()) return {};
  std::string sql = "INSERT INTO revision_tools (revision, tool) VALUES ";
  SqlParams params = {revision};
  for (const std::int64_t t : f.tools) {
    sql += fmt::format("{}(CAST($1 AS BIGINT), CAST(${} AS BIGINT))", params.size() > 1 ? ", " : "",
                       params.size() + 1);
    params.emplace_back(t);
  }
  auto tools = db.query(sql, params);
  if (!tools) return tl::unexpected(tools.error());
  return {};
}

}  // namespace

ProgramFacts read_facts(std::string_view text, std::string_view dialect) {
  return FactScan(text, rules_of(dialect)).run();
}

StoreResult<void> record_facts(Database& db, std::string_view program, std::string_view hash,
                               const ProgramFacts& facts) {
  auto rows =
      db.query("SELECT id FROM revisions WHERE program = $1 AND hash = $2", {program, hash});
  if (!rows) return tl::unexpected(rows.error());
  if (rows->empty()) {
    return store_error(StoreErrorKind::NotFound,
                       fmt::format("program {} has no revision {}", program, hash));
  }
  return record_facts_of(db, rows->front().integer(0), facts);
}

StoreResult<void> record_missing_facts(Database& db) {
  // A few revisions at a time: a store of large programs is never all in memory.
  constexpr std::int64_t kBatch = 32;
  std::int64_t after = 0;
  for (;;) {
    auto rows = db.query(
        "SELECT r.id, r.dialect, b.bytes FROM revisions r JOIN blobs b ON b.hash = r.hash "
        "WHERE r.id > $1 AND NOT EXISTS (SELECT 1 FROM revision_facts f WHERE f.revision = r.id) "
        "ORDER BY r.id LIMIT $2",
        {after, kBatch});
    if (!rows) return tl::unexpected(rows.error());
    for (const SqlRow& r : *rows) {
      after = r.integer(0);
      const ProgramFacts facts = read_facts(r.columns.at(2).value_or(""), r.text(1));
      if (auto made = record_facts_of(db, after, facts); !made) return made;
    }
    if (static_cast<std::int64_t>(rows->size()) < kBatch) return {};
  }
}

}  // namespace usina::dnc
