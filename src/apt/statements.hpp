// The statements that write CL records: post-processor words, tolerances
// and cutter, point-to-point motion (FROM, GOTO, GODLTA), END and FINI. A
// statement's records are kept only when the whole statement is correct.
#pragma once

#include <string>
#include <unordered_map>
#include <vector>

#include "apt/cl.hpp"
#include "apt/lexer.hpp"
#include "apt/processor.hpp"
#include "core/vec3.hpp"

namespace usina::apt {

class StatementRunner {
 public:
  StatementRunner(core::DiagnosticSink& diags, AptResult& out) : diags_(diags), out_(out) {}

  // The statement of words `t` from `i` on: "W, W, MAJOR/args" or "W".
  void words(const std::vector<Token>& t, std::size_t i, int isn, const core::SourceLoc& loc);
  // A text word (PARTNO, PPRINT, INSERT, REMARK) and its text.
  void text(const std::string& word, const std::string& text, int isn, const core::SourceLoc& loc);

  bool finished() const { return finished_; }

  SymbolTable& symbols() { return symbols_; }

  double zsurf() const { return zsurf_; }

 private:
  bool fail(const core::SourceLoc& at, core::Code code, std::string message);
  bool major(const Token& word, const std::vector<Arg>& args);
  bool motion(const Token& word, const std::vector<Arg>& args);
  bool godlta(const Token& word, const std::vector<Arg>& args);
  bool control(const Token& word, const std::vector<Arg>& args);
  bool post(const Token& word, int code, const std::vector<Arg>& args);
  bool modifiers(const std::vector<Token>& mods, const Token& major);
  void commit(int isn, const core::SourceLoc& loc);
  void add(int cls, int sub, std::vector<ClWord> words);

  core::DiagnosticSink& diags_;
  AptResult& out_;
  SymbolTable symbols_;
  std::vector<ClRecord> pending_;  // the records of the statement being read
  bool writes_ = false;            // whether the statement has a 1000 record
  core::Vec3 at_{};                // the tool end's position
  int lost_at_ = 0;  // the line of a motion not run, after which at_ is unknown (0: known)
  double zsurf_ = 0.0;
  bool finished_ = false;
};

}  // namespace usina::apt
