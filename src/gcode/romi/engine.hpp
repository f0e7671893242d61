// The front end of the romi dialect (spec/romi.md): cuts the text into
// blocks (romi_syntax), runs the Fagor parametric statements (P parameters,
// jumps, repeats, calls), evaluates each word and hands the block to romi's
// handlers (romi/translate.hpp), which check it by romi's table and hand the
// RS274NGC interpreter the engine owns its words: the one road below the
// text every dialect takes. No text is written for another part to read.
#pragma once

#include <array>
#include <optional>
#include <unordered_map>
#include <vector>

#include "gcode/dialect.hpp"
#include "gcode/expr.hpp"
#include "gcode/romi/codes.hpp"
#include "gcode/romi/services.hpp"
#include "gcode/romi/syntax.hpp"
#include "gcode/romi/translate.hpp"

namespace usina::gcode::romi {

// The romi dialect's table resolved (romi/dialect.cpp): made once, read by every run.
const CodeTable& code_table();

class Engine final : public ProgramRunner, private ParameterSource {
 public:
  Engine(const Dialect& dialect, const CodeTable& codes, RunContext context);

  void set_parameter(int index, double value) override;
  bool run(std::uint32_t file) override;

  // The modal state between blocks: after a failed block, as it was before.
  const Modal& state() const { return translator_.state(); }

  // Romi's modes as RS274NGC's words name them (G70/G71 are inch/mm, G81 a
  // canned cycle); a mirror, scale or rotation in force moves the frame.
  std::optional<RunModes> modes() const override;

  // Whether a handler of this name exists (every name in the dialect's
  // table must: a test checks).
  static bool knows_handler(std::string_view name) {
    return Translator::handler_named(name) != nullptr;
  }

 private:
  struct Cursor {
    std::uint64_t offset = 0;
    std::uint32_t line = 1;
    std::uint64_t line_start = 0;
  };

  struct Frame {
    bool call = false;  // (CALL n); otherwise (RPT ...)
    Cursor ret;
    double first = 0, last = 0;
    long remaining = 0;
  };

  struct IndexEntry {
    Cursor at;     // the block's start
    Cursor after;  // the next block's start
  };

  // ParameterSource: P0..P999 are read as named parameters "p<n>".
  double numbered(int index) const override;
  std::optional<double> named(std::string_view name) const override;

  bool error(core::Code code, std::uint32_t col, std::string message) {
    return run_.error(code, col, std::move(message));
  }

  // The block loop (romi/engine.cpp).
  void step();
  bool block();
  bool evaluate_words();
  bool plain_words(PlainMove& move) const;
  bool statements(bool flow);
  void end_of_program();

  // Control flow of the parametric statements (romi/flow.cpp).
  void build_index();
  bool jump_to_block(double n, std::uint32_t col);
  bool after_block_number();
  bool run_statement(const Statement& st);
  std::optional<double> statement_value(ExprRef e);
  bool repeat(const Statement& st);
  bool call(const Statement& st);
  bool skip_sub(const Statement& st);
  bool skip_to(std::uint64_t offset);

  const Dialect& dialect_;
  core::SourceManager& sources_;
  InterpOptions options_;
  Options dialect_options_;
  canon::Sink& sink_;
  core::DiagnosticSink& diags_;
  Services run_;
  Interpreter interp_;  // runs the machine: what the handlers hand it
  Translator translator_;

  RomiBlock block_;
  std::vector<EvaluatedWord> words_;  // the block's, evaluated (kept: no allocation a block)
  std::uint32_t file_ = 0;
  Cursor cursor_;
  LineEnd line_end_;  // of the line the cursor is on, when known (block_at)
  std::vector<Frame> frames_;
  std::optional<std::unordered_map<long, IndexEntry>> numbers_;
  std::unordered_map<long, Cursor> subs_;
  std::vector<std::uint64_t> returns_;  // offsets after each (RET) block
  std::array<double, kMaxParam + 1> params_{};
};

}  // namespace usina::gcode::romi
