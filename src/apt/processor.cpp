#include "apt/processor.hpp"

#include <algorithm>
#include <optional>
#include <string>
#include <unordered_map>

#include "apt/args.hpp"
#include "apt/lexer.hpp"
#include "apt/statements.hpp"

namespace usina::apt {
namespace {

// Text words take the rest of their statement as text.
bool is_text_word(std::string_view w) {
  return w == "PARTNO" || w == "PPRINT" || w == "INSERT" || w == "REMARK";
}

class Processor {
 public:
  Processor(core::DiagnosticSink& diags) : diags_(diags), run_(diags, out_) {}

  void statement(const Statement& st, int isn);
  void finish(const core::SourceLoc& last);

  AptResult take() { return std::move(out_); }

 private:
  bool fail(const core::SourceLoc& at, core::Code code, std::string message);
  void assignment(const std::vector<Token>& t, std::size_t i);
  void text_statement(const Statement& st, const Token& word, int isn);
  void synonyms(const std::vector<Token>& t, std::size_t i);

  std::unordered_map<std::string, std::string> syn_;  // SYN/GL,GOLFT: GL stands for GOLFT

  core::DiagnosticSink& diags_;
  AptResult out_;
  StatementRunner run_;
  bool ended_ = false;
};

bool Processor::fail(const core::SourceLoc& at, core::Code code, std::string message) {
  diags_.report({code, core::Severity::Error, at, std::move(message)});
  return false;
}

void Processor::statement(const Statement& st, int isn) {
  if (ended_) return;
  // A text word's text is not tokens: its lexical errors are said only
  // for other statements.
  core::DiagnosticList lexical;
  std::vector<Token> t = tokenize(st, lexical);
  for (Token& k : t) {
    const auto s = syn_.find(k.text);
    if (k.kind == TokKind::Word && s != syn_.end()) k.text = s->second;
  }
  std::size_t i = 0;
  if (t.size() > 2 && t[0].kind == TokKind::Word && t[1].text == ")") i = 2;  // label
  if (t[i].kind == TokKind::End) return;
  if (t[i].kind != TokKind::Word) {
    fail(t[i].loc, core::Code::AptSyntax,
         "a statement begins with a word (a name or a major word), not '" + t[i].text + "'");
    return;
  }
  if (is_text_word(t[i].text)) return text_statement(st, t[i], isn);
  for (const core::Diagnostic& d : lexical.all())
    diags_.report(d);
  if (t[i + 1].text == "=") return assignment(t, i);
  if (t[i].text == "SYN" && t[i + 1].text == "/") return synonyms(t, i + 2);
  run_.words(t, i, isn, st.loc);
  ended_ = run_.finished();
}

void Processor::synonyms(const std::vector<Token>& t, std::size_t i) {
  std::unordered_map<std::string, std::string> found;
  for (;;) {
    const bool pair =
        t[i].kind == TokKind::Word && t[i + 1].text == "," && t[i + 2].kind == TokKind::Word;
    if (!pair) {
      fail(t[i].loc, core::Code::AptSyntax,
           "SYN takes pairs of words, the synonym then the word: SYN/GL,GOLFT,GR,GORGT");
      return;
    }
    found[t[i].text] = t[i + 2].text;
    i += 3;
    if (t[i].kind == TokKind::End) break;
    if (t[i].text != ",") {
      fail(t[i].loc, core::Code::AptSyntax, "expected ',' between SYN pairs");
      return;
    }
    ++i;
  }
  syn_.merge(found);
}

void Processor::text_statement(const Statement& st, const Token& word, int isn) {
  std::string text = st.text.substr(word.pos + word.text.size());
  std::size_t k = 0;
  while (k < text.size() && text[k] == ' ')
    ++k;
  if (k < text.size() && text[k] == '/') text = text.substr(k + 1);
  run_.text(word.text, text, isn, st.loc);
}

void Processor::assignment(const std::vector<Token>& t, std::size_t i) {
  const Token& name = t[i];
  if (is_minor_word(name.text) || is_geometry_word(name.text)) {
    fail(name.loc, core::Code::AptSyntax,
         name.text + " is an APT vocabulary word; it cannot name a symbol");
    return;
  }
  const bool def = t[i + 2].kind == TokKind::Word && is_geometry_word(t[i + 2].text);
  ArgReader reader(t, i + 2, run_.symbols(), out_.definitions, run_.zsurf(), diags_,
                   run_.pattern_points());
  if (def) {
    auto g = reader.definition(false);
    if (!g) return;
    run_.symbols()[name.text] = Symbol{false, 0.0, *g};
    out_.definitions.push_back({name.text, *g, name.loc});
    return;
  }
  auto v = reader.whole_expression();
  if (v) run_.symbols()[name.text] = Symbol{true, *v, {}};
}

void Processor::finish(const core::SourceLoc& last) {
  run_.end_of_program();
  if (ended_) return;
  diags_.report({core::Code::AptNoFini, core::Severity::Warning, last,
                 "the program has no FINI; its end is taken as FINI"});
}

}  // namespace

AptResult process(std::string_view text, std::uint32_t file, core::DiagnosticSink& diags) {
  Processor p(diags);
  int isn = 0;
  core::SourceLoc last{file, 0, 0, 0, 0};
  for_each_statement(text, file, [&](const Statement& st) {
    last = st.loc;
    p.statement(st, ++isn);
  });
  p.finish(last);
  return p.take();
}

}  // namespace usina::apt
