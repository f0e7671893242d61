#include "apt/statements.hpp"

#include "apt/args.hpp"
#include "apt/vocabulary.hpp"

namespace usina::apt {
namespace {

// Motion words of the contouring part of the arithmetic, and the words that
// set its part surface and direction (statements_contour.cpp).
bool is_contour_word(std::string_view w) {
  return w == "GO" || w == "GOLFT" || w == "GORGT" || w == "GOFWD" || w == "GOBACK" ||
         w == "GOUP" || w == "GODOWN" || w == "PSIS" || w == "INDIRV" || w == "INDIRP";
}

// Words that only set listing or processor options: no CL record.
bool is_listing_word(std::string_view w) {
  return w == "CLPRNT" || w == "NOPOST" || w == "PRINT" || w == "ZSURF";
}

// Modal words for the contouring statements: a 1000 record, no other.
bool is_modal_word(std::string_view w) {
  return w == "TLLFT" || w == "TLRGT" || w == "TLON" || w == "NOPS" || w == "AUTOPS" ||
         w == "TLONPS" || w == "TLOFPS";
}

}  // namespace

bool StatementRunner::fail(const core::SourceLoc& at, core::Code code, std::string message) {
  diags_.report({code, core::Severity::Error, at, std::move(message)});
  return false;
}

void StatementRunner::add(int c, int sub, std::vector<ClWord> words) {
  pending_.push_back({c, sub, std::move(words), {}});
}

void StatementRunner::commit(int isn, const core::SourceLoc& loc) {
  if (writes_) {
    out_.records.push_back({cls::kSource, isn, {ClWord::number(0.0), ClWord::chars("")}, loc});
  }
  for (ClRecord& r : pending_) {
    r.src = loc;
    out_.records.push_back(std::move(r));
  }
  pending_.clear();
  writes_ = false;
}

void StatementRunner::text(const std::string& word, const std::string& text, int isn,
                           const core::SourceLoc& loc) {
  if (word == "REMARK") return;
  if (deferred_) resolve_deferred(Token{TokKind::Word, word, 0.0, 0, loc}, {});
  add(cls::kPost, *post_word_code(word), text_words(text, 11));
  writes_ = true;
  commit(isn, loc);
}

void StatementRunner::words(const std::vector<Token>& t, std::size_t i, int isn,
                            const core::SourceLoc& loc) {
  std::vector<Token> ws;
  bool slash = false;
  for (;;) {
    if (t[i].kind != TokKind::Word) {
      fail(t[i].loc, core::Code::AptSyntax, "expected a word, found '" + t[i].text + "'");
      return;
    }
    ws.push_back(t[i++]);
    if (t[i].text == "/") {
      slash = true;
      ++i;
      break;
    }
    if (t[i].kind == TokKind::End) break;
    if (t[i].text != ",") {
      fail(t[i].loc, core::Code::AptSyntax,
           "expected ',' or '/' after " + ws.back().text + ", found '" + t[i].text + "'");
      return;
    }
    ++i;
  }
  const Token major_word = ws.back();
  ws.pop_back();
  std::vector<Arg> args;
  if (slash) {
    ArgReader reader(t, i, symbols_, out_.definitions, zsurf_, diags_, pattern_points_);
    auto read = reader.arguments(major_word.text == "MACHIN");
    if (!read) return;
    args = std::move(*read);
  }
  pending_.clear();
  writes_ = false;
  isn_ = isn;
  if (deferred_) resolve_deferred(major_word, args);
  defer_now_ = false;
  if (!modifiers(ws, major_word) || !major(major_word, args)) {
    if (major_word.text.rfind("GO", 0) == 0 && is_contour_word(major_word.text))
      lost_at_ = static_cast<int>(loc.line);
    pending_.clear();
    return;
  }
  if (defer_now_) {  // waits for the next statement's drive surface
    deferred_->records = std::move(pending_);
    deferred_->isn = isn;
    deferred_->loc = loc;
    pending_.clear();
    writes_ = false;
    return;
  }
  commit(isn, loc);
}

bool StatementRunner::modifiers(const std::vector<Token>& mods, const Token& major_word) {
  for (const Token& m : mods) {
    if (m.text == "RAPID") {
      add(cls::kPost, 5, {});
      continue;
    }
    if (is_modal_word(m.text) && is_contour_word(major_word.text)) {
      if (!modal(m.text, {}, m.loc)) return false;
      continue;
    }
    return fail(m.loc, core::Code::AptSyntax, m.text + " cannot stand before " + major_word.text);
  }
  return true;
}

bool StatementRunner::major(const Token& word, const std::vector<Arg>& args) {
  const std::string& w = word.text;
  writes_ = true;
  if (w == "FROM" || w == "GOTO") return motion(word, args);
  if (w == "GODLTA") return godlta(word, args);
  if (w == "CUTTER" || w == "INTOL" || w == "OUTTOL" || w == "ZSURF") return control(word, args);
  if (is_listing_word(w)) {
    writes_ = false;
    return true;
  }
  if (is_modal_word(w)) return modal(w, args, word.loc);
  if (w == "FINI") {
    add(cls::kFini, 0, {});
    finished_ = true;
    return true;
  }
  if (const auto code = post_word_code(w)) return post(word, *code, args);
  if (is_contour_word(w)) return contour(word, args);
  return fail(word.loc, core::Code::AptNotSupported,
              "usina's APT does not run " + w + " (not a statement it knows)");
}

}  // namespace usina::apt
