#include "gcode/interp/interpreter.hpp"

#include <cmath>
#include <string_view>
#include <utility>

#include <fmt/format.h>

#include "core/copy_in_pieces.hpp"
#include "gcode/interp/block_words.hpp"
#include "gcode/parser.hpp"
#include "gcode/program_text.hpp"
#include "gcode/word_range.hpp"

namespace usina::gcode {

Interpreter::Interpreter(core::SourceManager& sources, InterpOptions options, canon::Sink& sink,
                         core::DiagnosticSink& diags, CycleHooks* cycle_hooks, DialectRules rules)
    : sources_(sources),
      options_(std::move(options)),
      rules_(rules),
      codes_(rules.codes != nullptr ? *rules.codes : rs274ngc_code_table()),
      order_(rules.order != nullptr ? *rules.order : linuxcnc_execution_order()),
      cycle_hooks_(cycle_hooks),
      sink_(sink),
      run_(diags, options_.max_total_iterations),
      machine_(sink, state_, diags),
      words_(std::make_unique<BlockWords>()) {
  // Programs start in mm whatever the machine's units, as LinuxCNC's
  // stand-alone interpreter does (the conformance traces depend on it).
  check_execution_order(order_);
  plain_moves_ = plain_moves_allowed(options_, codes_, order_);
  state_.units = core::LengthUnit::Mm;
  state_.motion = rules_.start_motion;
  set_xyz(state_.pos, options_.start);
}

Interpreter::~Interpreter() = default;

std::optional<int> Interpreter::whole(const BlockWords& w, char letter, int lo, int hi) {
  const double v = w.get(letter);
  const double r = std::round(v);
  // Written so that NaN fails: every comparison with it is false.
  if (!(std::fabs(v - r) <= 1e-4 && r >= lo && r <= hi)) {
    error(core::Code::BadWordValue, w.col_of(letter),
          fmt::format("{}{} must be a whole number from {} to {}", letter, v, lo, hi));
    return std::nullopt;
  }
  return static_cast<int>(r);
}

void Interpreter::start_from_parameters() {
  // The offsets a parameter file holds are in force from the start, as
  // LinuxCNC restores them when its interpreter starts.
  const double system = params_.get(5220);
  state_.coord_system = (system >= 1 && system <= 9) ? static_cast<int>(system) : 1;
  apply_work_offsets(state_.coord_system);
  if (params_.get(5210) != 0.0) {
    for (int a = 0; a < kAxisCount; ++a) {
      const double v = params_.get(5211 + a);
      state_.g92[static_cast<std::size_t>(a)] = (a >= 3 && a <= 5) ? v : v * machine_mm();
    }
  }
}

bool Interpreter::run(std::uint32_t file) {
  cursor_ = {file, 0, 1};
  start_from_parameters();
  const core::SourceFile* f = sources_.get(file);
  if (f == nullptr) return false;
  cursor_.offset = skip_byte_order_mark(f->text(), file, run_.diags());
  while (!ended_ && !run_.failed() && !at_eof_) {
    step();
    machine_faulted();
    // The sink's operation budget ran out (it reported why): end here.
    if (sink_.stopped()) run_.fail();
  }
  if (!run_.failed() && !ended_) {
    if (auto e = comp_.flush(machine_); !e) error(e.error());
  }
  machine_faulted();
  if (!run_.failed() && !ended_) {
    run_.at({file, cursor_.line > 1 ? cursor_.line - 1 : 1, 0, 0, 0});
    warn(core::Code::NoProgramEnd, 0,
         "the program ends without M2, M30 or '%'; taken as its end (LinuxCNC reports an error)");
  }
  sink_.finish();
  return !run_.failed();
}

Interpreter::Flow Interpreter::step() {
  core::SourceFile* f = sources_.get(cursor_.file);
  if (cursor_.offset >= f->text().size()) return end_of_file() ? Flow::Next : Flow::End;
  const LineView lv = line_at(f->text(), cursor_.offset);
  f->release_before(cursor_.offset);
  const LinePos where{cursor_.file, cursor_.line, cursor_.offset};
  cursor_.offset = lv.next;
  ++cursor_.line;
  if (auto length = check_block_length(lv.text, {where.file, where.line, 1, 0, where.offset});
      !length) {
    run_.diags().report(std::move(length.error()));
    run_.fail();
    return Flow::Error;
  }
  if (!parse_block(lv.text, where, block_, run_.diags())) {
    run_.fail();
    return Flow::Error;
  }
  run_.at(block_.loc);
  machine_.set_source(run_.loc());
  if (block_.percent) return percent_line(where);
  if (block_.deleted && options_.block_delete) return Flow::Next;
  if (block_.o) return control(*block_.o, where.offset);
  if (block_.empty()) return Flow::Next;
  if (!evaluate(block_) || !run_evaluated(evaluated(block_))) return Flow::Error;
  return ended_ ? Flow::End : Flow::Next;
}

bool Interpreter::run_evaluated(const EvaluatedBlock& block) {
  if (marked_ == Marked::Pending) take_checkpoint();
  const bool checkpointed = std::exchange(checkpoint_fresh_, false);
  if (run_.failed() || ended_) return !run_.failed();
  run_.at(block.loc);
  machine_.set_source(run_.loc());
  if (block.empty()) return true;
  if (plain_moves_) {
    if (const std::optional<bool> ran = plain_move(block)) return *ran;
  }
  BlockWords& w = *words_;
  if (!sort_words(block.words, w) || !assign(block.assigns) || !check(w)) return false;
  // The block works on a copy of the modal state: a failed block changes
  // nothing. A checkpoint taken just before it holds that copy already
  // (Grbl's every line: the second copy was a tenth of its check, issue 19).
  if (checkpointed) return execute_from(checkpoint_->state, block.comments, w);
  ModalState before;
  core::copy_in_pieces(before, state_);
  return execute_from(before, block.comments, w);
}

bool Interpreter::execute_from(const ModalState& before, std::span<const CommentText> comments,
                               BlockWords& w) {
  if (!execute(comments, w) || machine_faulted()) {
    state_ = before;
    return false;
  }
  return true;
}

void Interpreter::hole(const core::SourceLoc& loc, const Vec3& top, double depth) {
  machine_.set_source(loc);
  machine_.hole(top, depth);
}

void Interpreter::pocket(const core::SourceLoc& loc, canon::Outline outline, double depth) {
  machine_.set_source(loc);
  const auto place = [this](Vec2 q) {
    const Vec3 a = machine_.to_absolute({q.x, q.y, 0.0});
    return Vec2{a.x, a.y};
  };
  outline.start = place(outline.start);
  for (canon::OutlineSegment& s : outline.segs) {
    s.to = place(s.to);
    if (s.center) s.center = place(*s.center);
  }
  machine_.emit(canon::Pocket{std::move(outline), depth});
}

bool Interpreter::finish() {
  if (!run_.failed() && !ended_) {
    if (auto e = comp_.flush(machine_); !e) error(e.error());
  }
  machine_faulted();
  sink_.finish();
  return !run_.failed();
}

// The canonical machine refused an op (and reported why): the run stops
// there, as at any other error.
bool Interpreter::machine_faulted() {
  if (machine_.faulted()) run_.fail();
  return machine_.faulted();
}

bool Interpreter::sort_words(std::span<const EvaluatedWord> words, BlockWords& w) {
  w.reset();
  for (const EvaluatedWord& word : words) {
    if (!sort_word(word, w)) return false;
  }
  return true;
}

// A word into its place: a code into its modal group (codes are read in
// tenths, G38.2 → 382; M codes are whole numbers), any other letter once.
bool Interpreter::sort_word(const EvaluatedWord& word, BlockWords& w) {
  const double v = word.value;
  if (!word_value_in_range(word.letter, v)) {
    return error(core::Code::ValueOutOfRange, word.col, word_range_error(word.letter, v));
  }
  if (word.letter == 'G' || word.letter == 'M') {
    // No code is negative or past G9999 (NaN fails here too); within
    // those, v * 10 to the nearest whole number, halves up.
    if (!(v >= 0.0 && v <= 10000.0)) return word_refused(word, core::Code::UnknownGCode);
    const double scaled = v * 10.0;
    const double tenths = static_cast<double>(static_cast<long long>(scaled + 0.5));
    if (tenths > 99990 || std::fabs(scaled - tenths) > 1e-6 ||
        (word.letter == 'M' && static_cast<long>(tenths) % 10 != 0)) {
      return word_refused(word, core::Code::UnknownGCode);
    }
    const int code = static_cast<int>(tenths);
    return word.letter == 'G' ? place_g(w, code, word.col) : place_m(w, code / 10, word.col);
  }
  if (w.has(word.letter)) return word_refused(word, core::Code::RepeatedWord);
  if (word.incremental) {
    if (std::string_view(kAxisLetters).find(word.letter) == std::string_view::npos) {
      return word_refused(word, core::Code::NotAllowedInMode);
    }
    w.mark_incremental(word.letter);
  }
  w.set(word.letter, v, word.col);
  return true;
}

// Why sort_word refused a word: apart, so the way of every accepted word
// builds no message.
bool Interpreter::word_refused(const EvaluatedWord& word, core::Code why) {
  switch (why) {
  case core::Code::RepeatedWord:
    return error(why, word.col, fmt::format("{} word appears twice in the block", word.letter));
  case core::Code::NotAllowedInMode:
    return error(why, word.col,
                 fmt::format("{} written as an increment: only axis words may be", word.letter));
  default:
    return error(word.letter == 'G' ? core::Code::UnknownGCode : core::Code::UnknownMCode, word.col,
                 fmt::format("{}{} is not a code", word.letter, word.value));
  }
}

bool Interpreter::assign(std::span<const EvaluatedAssign> assigns) {
  for (const EvaluatedAssign& a : assigns) {
    if (a.index > 0) {
      params_.set(a.index, a.value);
      if (a.index >= 5161 && a.index <= 5389) state_.offsets_written = true;
    } else if (predefined(a.name)) {
      return error(core::Code::ReadOnlyParameter, a.col,
                   fmt::format("#<{}> is a read-only parameter", a.name));
    } else {
      params_.set_named(a.name, a.value);
    }
  }
  return true;
}

}  // namespace usina::gcode
