#include "gcode/romi/engine.hpp"

#include <cmath>

#include <fmt/format.h>

#include "gcode/program_text.hpp"
#include "gcode/word_range.hpp"

namespace usina::gcode::romi {

Engine::Engine(const Dialect& dialect, const CodeTable& codes, RunContext context)
    : dialect_(dialect),
      sources_(context.sources),
      options_(std::move(context.options)),
      dialect_options_(Options::from(dialect, context.dialect_options)),
      sink_(context.sink),
      diags_(context.diags),
      run_(context.diags, options_.max_total_iterations),
      interp_(context.sources, options_, context.sink, context.diags, nullptr, romi_rules()),
      translator_(codes, run_, options_, dialect_options_, interp_) {}

void Engine::set_parameter(int index, double value) {
  if (index >= 0 && index <= kMaxParam) params_[static_cast<std::size_t>(index)] = value;
}

double Engine::numbered(int) const {
  return 0.0;
}

std::optional<double> Engine::named(std::string_view name) const {
  // "p12": the parser only makes names of P and 1-3 digits.
  if (name.size() < 2 || name[0] != 'p') return std::nullopt;
  int n = 0;
  for (const char c : name.substr(1)) {
    if (c < '0' || c > '9') return std::nullopt;
    n = n * 10 + (c - '0');
    if (n > kMaxParam) return std::nullopt;
  }
  return params_[static_cast<std::size_t>(n)];
}

bool Engine::run(std::uint32_t file) {
  file_ = file;
  cursor_ = {};
  const core::SourceFile* f = sources_.get(file);
  if (f == nullptr) return false;
  cursor_.offset = skip_byte_order_mark(f->text(), file, diags_);
  translator_.start(dialect_.start_codes, {file, 1, 1, 0, 0});
  while (!translator_.ended() && !run_.failed() && cursor_.offset < f->text().size()) {
    step();
    if (sink_.stopped()) run_.fail();  // the operation budget ran out
  }
  end_of_program();
  return !run_.failed();
}

// The end of the run: what compensation holds goes out (the interpreter's
// finish), and a program that ends without M02/M30 gets a warning that the
// end was taken. After an error nothing more goes out.
void Engine::end_of_program() {
  const bool open = !run_.failed() && !translator_.ended();
  if (open) translator_.finish();
  if (run_.failed()) {
    sink_.finish();
    return;
  }
  if (!interp_.finish()) run_.fail();
  if (open && !run_.failed()) {
    run_.at({file_, cursor_.line > 1 ? cursor_.line - 1 : 1, 0, 0, 0});
    run_.note(core::Code::NoProgramEnd, core::Severity::Warning, 0,
              "the program ends without M02 or M30; taken as its end");
  }
}

void Engine::step() {
  core::SourceFile* f = sources_.get(file_);
  // The text behind the block's line is not needed again unless a jump
  // goes back to it (then it is read again from the file): memory stays
  // flat however long the program (issue 19).
  f->release_before(cursor_.line_start);
  const BlockText bt = block_at(f->text(), cursor_.offset, line_end_);
  const auto col = static_cast<std::uint32_t>(cursor_.offset - cursor_.line_start + 1);
  const LinePos where{file_, cursor_.line, cursor_.line_start};
  cursor_.offset = bt.next;
  if (bt.ends_line) {
    ++cursor_.line;
    cursor_.line_start = bt.next;
  }
  // Nothing after a line's last '#', how romi lines end ("G01 X10#"):
  // every other block cut in a program of a block a line, and the parser
  // would find no block in it.
  if (bt.text.empty()) return;
  if (auto length = check_block_length(bt.text, {file_, where.line, col, 1, where.offset});
      !length) {
    diags_.report(std::move(length.error()));
    run_.fail();
    return;
  }
  if (!parse_romi_block(bt.text, where, col, block_, diags_)) {
    run_.fail();
    return;
  }
  if (block_.base.percent) return;
  // Nothing between a '#' and the line's end (how romi programs are
  // written: "G01 X10#" a line) is no block: it runs nothing, and an R
  // blend waits for the next block that moves, not for it.
  if (block_.empty() && block_.base.comments.empty() && !block_.base.line_number) return;
  run_.at(block_.base.loc);
  if (!block()) {
    run_.fail();
    return;
  }
  if (!translator_.ended() && !run_.failed()) after_block_number();
}

// The block's steps around the handlers': the dashes read as minus signs,
// the assignments, the words evaluated and run, the jumps.
bool Engine::block() {
  for (const std::uint32_t dash : block_.dashes) {
    if (dialect_options_.typographic_dash_is_error) {
      return error(core::Code::TypographicDash, dash,
                   "a typographic dash instead of '-' (typographic_dash=error)");
    }
    run_.note(core::Code::TypographicDash, core::Severity::Warning, dash,
              "a typographic dash read as a minus sign");
  }
  if (PlainMove move; plain_words(move)) {
    if (const std::optional<bool> ran = translator_.run_plain_move(block_.base.loc, move))
      return *ran;
  }
  if (!statements(false) || !evaluate_words()) return false;
  const EvaluatedBlock evaluated{block_.base.loc, words_, {}, block_.base.comments};
  // No jump to run after most blocks: no call through a std::function.
  if (block_.statements.empty()) return translator_.run_evaluated(evaluated);
  return translator_.run_evaluated(evaluated, [this] { return statements(true); });
}

// Step 1: every word's value, with its column, and lower-case words marked
// as increments when the dialect's option says so.
bool Engine::evaluate_words() {
  // Sized once and written in place, as the interpreter's evaluate() does
  // (a push_back a word, issue 19); cut back to the words read on an error.
  words_.resize(block_.words.size());
  EvaluatedWord* out = words_.data();
  const auto fail = [&](core::Code code, std::uint32_t col, std::string message) {
    words_.resize(static_cast<std::size_t>(out - words_.data()));
    return error(code, col, std::move(message));
  };
  for (const RomiWord& w : block_.words) {
    double v = w.number;
    if (w.value != kPlainNumber) {
      EvalError err;
      const auto e = gcode::evaluate(block_.base, w.value, *this, err);
      if (!e) return fail(err.error.code, err.col, err.error.message);
      v = *e;
    }
    if (!word_value_in_range(w.letter, v)) {
      return fail(core::Code::ValueOutOfRange, w.col, word_range_error(w.letter, v));
    }
    const bool incremental = w.lower && dialect_options_.lowercase_incremental;
    *out++ = {w.letter, v, w.col, incremental};
  }
  return true;
}

std::optional<RunModes> Engine::modes() const {
  const Modal& m = translator_.state();
  RunModes out;
  out.inch = m.machine.units == core::LengthUnit::Inch;
  out.incremental = m.machine.incremental;
  out.motion = m.drill.active ? 810 : m.machine.motion;
  const Transform& t = m.tf;
  out.frame_moved =
      t.mirror_x || t.mirror_y || t.scale_x != 1.0 || t.scale_y != 1.0 || t.rotation_deg != 0.0;
  return out;
}

}  // namespace usina::gcode::romi
