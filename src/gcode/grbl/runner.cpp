// The grbl runner: one pass over the program in constant memory. Grbl
// reports an error for a line it refuses and reads the next one ("report
// and continue"); a refused line changes nothing, in Grbl's state as in the
// interpreter's (Interpreter::checkpoint), and sends no op. The lines are
// read where they lie in the file, the ops of a line are held until its
// checks passed, then streamed: nothing grows with the program's length.
#include "gcode/grbl/runner.hpp"

#include <optional>
#include <string>

#include "gcode/grbl/dialect.hpp"
#include "gcode/grbl/machine_check.hpp"
#include "gcode/grbl/reader.hpp"
#include "gcode/program_text.hpp"

namespace usina::gcode::grbl {
namespace {

// Grbl powers up in G0, and a G54-G59 word re-reads its system's offsets.
constexpr DialectRules kGrbl{.start_motion = 0, .reselect_reloads_work_offsets = true};

// Holds the ops of the line being run until its checks passed. A
// straight move goes by unbuilt when the run's sink reads no op; its end
// is then where the interpreter's last move ended.
class LineOps final : public canon::Sink {
 public:
  // The run's sink answers the same all run (the sinks of canon/ do):
  // asked once, not for every move.
  explicit LineOps(const canon::Sink& next) : reads_ops_(next.reads_ops()) {}

  void on(const canon::Op& op) override { moves.built.push_back(op); }

  bool reads_ops() const override { return reads_ops_; }

  void pass(const core::SourceLoc& src) override {
    moves.passed.push_back({moves.built.size(), src, interp_->last_move_end()});
  }

  // The interpreter whose ops these are.
  void follow(const Interpreter& interp) { interp_ = &interp; }

  LineMoves moves;

 private:
  bool reads_ops_;
  const Interpreter* interp_ = nullptr;
};

// The interpreter's error as Grbl's, when Grbl has a number for it.
core::Diagnostic as_grbl(core::Diagnostic d) {
  if (const int n = error_for(d.code); n > 0) {
    d.code = core::Code::GrblError;
    d.message = error_message(n, d.message);
  }
  return d;
}

std::optional<core::Diagnostic> first_error(const core::DiagnosticList& diags) {
  for (const core::Diagnostic& d : diags.all())
    if (d.severity == core::Severity::Error) return as_grbl(d);
  return std::nullopt;
}

// One run: the lines in order, each read by Grbl's rules, run, checked,
// then its diagnostics reported and its ops passed on.
class Pass {
 public:
  Pass(RunContext& c, const Dialect& d, std::uint32_t file)
      : c_(c),
        file_(file),
        stop_(c.dialect_options.at("after_error") == "stop"),
        reader_(d, c.dialect_options, file),
        ops_(c.sink),
        interp_(c.sources, c.options, ops_, interp_diags_, nullptr, kGrbl),
        check_(c.options.start) {
    ops_.follow(interp_);
  }

  Interpreter& interpreter() { return interp_; }

  bool run(core::SourceFile& source);

 private:
  void line(std::uint32_t n, std::uint64_t offset, std::string_view text);
  bool hand_over(std::uint32_t n, std::uint64_t offset);
  bool run_line(const core::SourceLoc& loc);
  void refuse(core::Diagnostic failure);
  void report_line();

  RunContext& c_;
  std::uint32_t file_;
  bool stop_;
  LineReader reader_;
  LineOps ops_;
  core::DiagnosticList interp_diags_;  // the line's, from the interpreter
  Interpreter interp_;
  MachineCheck check_;
  std::vector<core::Diagnostic> line_diags_;  // the line's, reported when it is done
  bool ended_ = false;                        // an alarm, or an error with after_error=stop
  bool ok_ = true;
};

bool Pass::run(core::SourceFile& source) {
  const std::string_view text = source.text();
  // Grbl's serial reader throws the mark's bytes away (above 0x7F);
  // strip_line does the same.
  skip_byte_order_mark(text, file_, c_.diags);
  interp_.start_from_parameters();
  std::uint32_t n = 0;
  for (std::uint64_t at = 0; at < text.size() && !ended_;) {
    const LineSpan l = read_line(text, at);
    at = l.next;
    source.release_before(l.offset);
    line(++n, l.offset, text.substr(l.offset, l.length));
    // The sink's operation budget ran out (it reported why): end here.
    if (c_.sink.stopped()) ended_ = true;
  }
  interp_.finish();
  c_.sink.finish();
  return ok_ && !c_.sink.stopped();
}

void Pass::line(std::uint32_t n, std::uint64_t offset, std::string_view text) {
  switch (reader_.read(n, offset, text, line_diags_)) {
  case LineKind::Nothing: break;
  case LineKind::Refused: ended_ = stop_; break;
  case LineKind::Run:
    if (hand_over(n, offset)) reader_.accept();
    break;
  }
  report_line();
}

// The line's words to the interpreter, and its ops to Grbl's checks from
// the position; true when both accept it, and its ops are then passed on.
// A refused line is rolled back in the interpreter, its ops dropped.
bool Pass::hand_over(std::uint32_t n, std::uint64_t offset) {
  ops_.moves.clear();
  interp_diags_.clear();
  interp_.checkpoint();
  const core::SourceLoc loc{file_, n, reader_.block_col(), 0, offset};
  const bool ran = run_line(loc);
  std::optional<core::Diagnostic> failure = check_.block(ops_.moves, reader_.facts());
  if (!failure && !ran) failure = first_error(interp_diags_);
  if (!ran || failure) {
    interp_.roll_back();
    if (failure) refuse(std::move(*failure));
    return false;
  }
  for (const core::Diagnostic& d : interp_diags_.all())
    line_diags_.push_back(d);
  ops_.moves.each(
      [&](const canon::Op& op) {
        c_.sink.on(op);
        return true;
      },
      [&](const LineMoves::Passed& p) {
        c_.sink.pass(p.src);
        return true;
      });
  return true;
}

// The line in the interpreter: a plain move as one, when the interpreter's
// state lets it by, else its words.
bool Pass::run_line(const core::SourceLoc& loc) {
  if (const PlainMove* move = reader_.plain_move()) {
    if (const std::optional<bool> ran = interp_.run_plain_move(loc, *move)) return *ran;
  }
  const HandedBlock& block = reader_.handed();
  return interp_.run_evaluated({loc, block.words, block.assigns, {}});
}

// An error of the interpreter or of the checks from the position: Grbl
// reports it and reads on, unless it is an alarm (Grbl locks out every line
// after one) or after_error=stop; then the run ends at the line, whose
// other diagnostics go with it.
void Pass::refuse(core::Diagnostic failure) {
  if (stop_ || failure.code == core::Code::GrblAlarm) {
    line_diags_.clear();
    ended_ = true;
  }
  line_diags_.push_back(std::move(failure));
}

void Pass::report_line() {
  for (core::Diagnostic& d : line_diags_) {
    ok_ = ok_ && d.severity != core::Severity::Error;
    c_.diags.report(std::move(d));
  }
  line_diags_.clear();
}

}  // namespace

bool Runner::run(std::uint32_t file) {
  core::SourceFile* source = c_.sources.get(file);
  if (source == nullptr) return false;
  Pass pass(c_, dialect_, file);
  for (const auto& [index, value] : params_)
    pass.interpreter().set_parameter(index, value);
  const bool ok = pass.run(*source);
  modes_ = run_modes(pass.interpreter().state());
  return ok;
}

}  // namespace usina::gcode::grbl
