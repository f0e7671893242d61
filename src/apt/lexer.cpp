#include "apt/lexer.hpp"

#include <cctype>
#include <charconv>
#include <cstdlib>

namespace usina::apt {
namespace {

bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\r';
}

// A physical line's text up to '$$', and whether it ends in a continuing '$'.
std::string_view strip_comment(std::string_view line, bool& continues) {
  const auto cc = line.find("$$");
  if (cc != std::string_view::npos) line = line.substr(0, cc);
  while (!line.empty() && is_blank(line.back()))
    line.remove_suffix(1);
  continues = !line.empty() && line.back() == '$';
  if (continues) line.remove_suffix(1);
  return line;
}

void append(Statement& st, std::string_view part, core::SourceLoc at) {
  for (std::size_t i = 0; i < part.size(); ++i) {
    core::SourceLoc l = at;
    l.col = at.col + static_cast<std::uint32_t>(i);
    l.length = 1;
    st.text.push_back(part[i]);
    st.where.push_back(l);
  }
}

bool only_blanks(const std::string& s) {
  for (char c : s)
    if (!is_blank(c)) return false;
  return true;
}

}  // namespace

void for_each_statement(std::string_view text, std::uint32_t file,
                        const std::function<void(const Statement&)>& take) {
  Statement cur;
  bool open = false;
  std::uint32_t line_no = 0;
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t eol = text.find('\n', pos);
    if (eol == std::string_view::npos) eol = text.size();
    ++line_no;
    bool continues = false;
    const std::string_view body = strip_comment(text.substr(pos, eol - pos), continues);
    core::SourceLoc at{file, line_no, 1, 0, pos};
    if (!open) {
      cur = Statement{};
      cur.loc = at;
    } else {
      cur.text.push_back(' ');  // a continuation is a separate word
      cur.where.push_back(at);
    }
    append(cur, body, at);
    open = continues;
    if (!open && !only_blanks(cur.text)) take(cur);
    pos = eol + 1;
  }
  if (open && !only_blanks(cur.text)) take(cur);
}

std::vector<Statement> split_statements(std::string_view text, std::uint32_t file) {
  std::vector<Statement> out;
  for_each_statement(text, file, [&out](const Statement& st) { out.push_back(st); });
  return out;
}

core::SourceLoc loc_at(const Statement& st, std::size_t i) {
  if (st.where.empty()) return st.loc;
  if (i >= st.where.size()) {
    core::SourceLoc l = st.where.back();
    l.col += 1;
    return l;
  }
  return st.where[i];
}

namespace {

std::size_t lex_number(const std::string& s, std::size_t i, Token& t) {
  std::size_t j = i;
  while (j < s.size() && (std::isdigit(static_cast<unsigned char>(s[j])) || s[j] == '.'))
    ++j;
  if (j < s.size() && (s[j] == 'E' || s[j] == 'e') && j + 1 < s.size()) {
    std::size_t k = j + 1;
    if (s[k] == '+' || s[k] == '-') ++k;
    if (k < s.size() && std::isdigit(static_cast<unsigned char>(s[k]))) {
      j = k;
      while (j < s.size() && std::isdigit(static_cast<unsigned char>(s[j])))
        ++j;
    }
  }
  t.kind = TokKind::Number;
  t.text = s.substr(i, j - i);
  t.value = std::strtod(t.text.c_str(), nullptr);
  return j;
}

std::size_t lex_word(const std::string& s, std::size_t i, Token& t) {
  std::size_t j = i;
  while (j < s.size() && (std::isalnum(static_cast<unsigned char>(s[j])) || s[j] == '_'))
    ++j;
  t.kind = TokKind::Word;
  t.text.clear();
  for (std::size_t k = i; k < j; ++k)
    t.text.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(s[k]))));
  return j;
}

}  // namespace

std::vector<Token> tokenize(const Statement& st, core::DiagnosticSink& diags) {
  std::vector<Token> out;
  const std::string& s = st.text;
  std::size_t i = 0;
  while (i < s.size()) {
    const char c = s[i];
    if (is_blank(c)) {
      ++i;
      continue;
    }
    Token t;
    t.loc = loc_at(st, i);
    const std::size_t start = i;
    if (std::isdigit(static_cast<unsigned char>(c)) ||
        (c == '.' && i + 1 < s.size() && std::isdigit(static_cast<unsigned char>(s[i + 1])))) {
      i = lex_number(s, i, t);
    } else if (std::isalpha(static_cast<unsigned char>(c))) {
      i = lex_word(s, i, t);
    } else if (std::string_view("/,()=+-*").find(c) != std::string_view::npos) {
      t.kind = TokKind::Punct;
      // One assignment: assigning "**" over the one-character text made
      // GCC 12 at -O3 warn of an uninitialised read (a false
      // -Wmaybe-uninitialized inside std::string).
      const bool power = c == '*' && i + 1 < s.size() && s[i + 1] == '*';
      t.text = power ? std::string("**") : std::string(1, c);
      i += power ? 2 : 1;
    } else {
      diags.report({core::Code::AptSyntax, core::Severity::Error, t.loc,
                    "character '" + std::string(1, c) +
                        "' is not APT; remove it (APT has letters, digits and / , ( ) = + - * $)"});
      ++i;
      continue;
    }
    t.loc.length = static_cast<std::uint32_t>(i - start);
    t.pos = start;
    out.push_back(std::move(t));
  }
  Token end;
  end.loc = loc_at(st, s.size());
  out.push_back(end);
  return out;
}

}  // namespace usina::apt
