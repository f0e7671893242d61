// The grbl runner: the checks of every line, the copy the interpreter runs,
// and the reruns that let Grbl's "report and read on" hold for the errors
// only the interpreter finds (arc geometry, probe targets).
#include "gcode/dialects/grbl_runner.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <limits>

#include <fmt/format.h>

#include "core/arc.hpp"
#include "gcode/program_text.hpp"

namespace usina::gcode::grbl {
namespace {

std::string motion_name(int tenths) {
  return tenths % 10 == 0 ? fmt::format("G{}", tenths / 10)
                          : fmt::format("G{}.{}", tenths / 10, tenths % 10);
}

// The modes a `$J=` jog or `$H` changed in the interpreter and Grbl kept:
// put back on the next G-code line (distance, feed mode, F) and on the next
// line moving with the modal motion (the motion mode).
struct Restore {
  bool modes = false;
  bool motion = false;
  Modal before;
};

// Reads the program line by line as Grbl does and writes the interpreter's copy.
class Preparer {
 public:
  Preparer(const Dialect& d, const OptionValues& o, std::uint32_t file)
      : d_(d), options_(o), file_(file), max_length_(line_length(o)) {}

  Prepared out;

  void line(std::uint32_t n, std::uint64_t offset, std::string_view text, bool refused) {
    loc_ = {file_, n, 1, 0, offset};
    if (!ended_ && !refused) {
      if (auto too_long = block_too_long(text, loc_)) {
        out.diags.push_back(std::move(*too_long));
        failed_ = true;
        return blank();
      }
    }
    const StrippedLine s = strip_line(text);
    if (ended_) {
      if (!s.text.empty() && s.text != "%" && !warned_after_end_) {
        warn(
            core::Code::TextAfterProgramEnd, 1,
            "lines after M2/M30: Grbl goes on reading them, usina's trace ends at the program end");
        warned_after_end_ = true;
      }
      return blank();
    }
    if (s.control_col > 0) {
      warn(core::Code::GrblWarning, s.control_col,
           fmt::format("control character 0x{:02x}: Grbl drops it as it drops blanks, so the "
                       "characters around it join (X1, NUL, 20 reads X120); usina reads the line "
                       "as Grbl does: check the file for damage",
                       s.control));
    }
    if (s.realtime_col > 0) {
      warn(core::Code::GrblWarning, s.realtime_col,
           "'?', '~', '!' and Ctrl-X are Grbl real-time commands (status, cycle start, feed hold, "
           "reset), taken out of the stream wherever they are; usina drops them");
    }
    if (s.text.empty() || s.text == "%" || refused) return blank();
    if (s.text.size() > max_length_) {
      return fail({11, 1,
                   fmt::format("{} characters after blanks and comments are removed; Grbl "
                               "holds {}",
                               s.text.size(), max_length_)});
    }
    if (s.text[0] == '$') {
      system(n, s);
      return record(n);
    }
    std::vector<Word> words;
    if (auto f = read_words(s.text, s.cols, words)) return fail(*f);
    const Modal before = state_;
    Accepted acc;
    if (auto f = check_block(d_, options_, words, state_, acc)) return fail(*f);
    out.text += s.blanked + appended(acc, before);
    out.text += '\n';
    if (acc.program_end) ended_ = true;
    record(n);
  }

  bool failed() const { return failed_; }

 private:
  void blank() { out.text += '\n'; }

  void fail(const Failure& f) {
    core::SourceLoc at = loc_;
    at.col = f.col;
    at.length = 1;
    out.diags.push_back(
        {core::Code::GrblError, core::Severity::Error, at, error_message(f.number, f.detail)});
    failed_ = true;
    blank();
  }

  void warn(core::Code code, std::uint32_t col, std::string message) {
    core::SourceLoc at = loc_;
    at.col = col;
    out.diags.push_back({code, core::Severity::Warning, at, std::move(message)});
  }

  // What the soft-limit check needs from this line on.
  void record(std::uint32_t n) {
    out.facts.record(n, {Travel::of(settings_), state_.tool_length_mm});
  }

  void system(std::uint32_t n, const StrippedLine& s) {
    SystemResult r = system_command(d_, options_, s.text, s.cols, state_, settings_);
    for (std::string& w : r.warnings)
      warn(core::Code::GrblWarning, s.cols.front(), std::move(w));
    if (r.failure) return fail(*r.failure);
    if (r.restore_modes && !restore_.modes && !restore_.motion) restore_.before = state_;
    if (r.restore_modes) restore_.modes = restore_.motion = true;
    if (r.reset) {
      // Grbl's G0 goes on the next line moving with the modal motion: a G0
      // of its own is a move to where the tool is for the interpreter.
      state_ = Modal{};
      restore_ = Restore{};
      restore_.motion = true;
    }
    if (r.jog) out.facts.jogs.insert(n);
    if (r.homing) out.facts.homing.insert(n);
    out.text += r.interp_line;
    out.text += '\n';
  }

  // Grbl's LINE_BUFFER_SIZE (config.h) less its terminator.
  static std::size_t line_length(const OptionValues& o) {
    const auto it = o.find("line_buffer");
    return it == o.end() ? kMaxLineLength : std::stoul(it->second) - 1;
  }

  // The words the interpreter's copy of an accepted block needs besides
  // Grbl's: the modes a jog or `$H` changed.
  std::string appended(const Accepted& acc, const Modal& before) {
    std::string extra;
    const double per_unit = before.inch ? 25.4 : 1.0;
    if (restore_.modes) {
      const Modal& p = restore_.before;
      if (!acc.sets_distance) extra += p.incremental ? " G91" : " G90";
      if (!acc.sets_feed_mode) extra += p.inverse_time ? " G93" : " G94";
      if (!acc.sets_feed) {
        extra += fmt::format(" F{:.12f}", p.inverse_time ? p.feed_mm : p.feed_mm / per_unit);
      }
      restore_.modes = false;
    }
    if (acc.uses_motion && restore_.motion) extra += " " + motion_name(restore_.before.motion);
    if (acc.uses_motion || acc.sets_motion) restore_.motion = false;
    return extra;
  }

  const Dialect& d_;
  const OptionValues& options_;
  std::uint32_t file_;
  std::size_t max_length_;
  core::SourceLoc loc_;
  Modal state_;
  Settings settings_;
  Restore restore_;
  bool ended_ = false;
  bool warned_after_end_ = false;
  bool failed_ = false;
};

// Checks what Grbl checks from the position: the arc end on the circle
// within Grbl's tolerance, a probe going somewhere, the soft limits; and
// passes the ops on (`forward`) in the run whose lines are all accepted, so
// nothing is held.
class CheckingSink final : public canon::Sink {
 public:
  CheckingSink(const core::Vec3& start, const MachineFacts& facts) : pos_(start), facts_(facts) {}

  std::function<void(const canon::Op&)> forward;
  const canon::Sink* downstream = nullptr;  // what `forward` sends to, for stopped()
  std::optional<core::Diagnostic> failure;

  bool stopped() const override { return downstream != nullptr && downstream->stopped(); }

  void on(const canon::Op& op) override {
    if (forward) forward(op);
    if (failure) return;
    if (const auto* a = std::get_if<canon::Arc>(&op.kind)) check_arc(*a, op.src);
    if (const auto* p = std::get_if<canon::Probe>(&op.kind)) {
      if (known_ && core::norm(p->to - pos_) < 1e-9) {
        fail(op.src, 33, "the probe target is the current position");
      }
      travel(p->to, op.src);
      known_ = false;  // the probe stops short of its target: the next start is not `to`
      return;
    }
    if (const auto* t = std::get_if<canon::Traverse>(&op.kind)) moved(t->to, op.src);
    if (const auto* f = std::get_if<canon::Feed>(&op.kind)) moved(f->to, op.src);
    if (const auto* s = std::get_if<canon::Spline>(&op.kind)) {
      for (const core::Vec3& q : s->points)
        travel(q, op.src);
      moved(s->to, op.src);
    }
  }

 private:
  void moved(const core::Vec3& to, const core::SourceLoc& src) {
    travel(to, src);
    pos_ = to;
    known_ = true;
  }

  // Grbl's soft limits (mc_line → limits_soft_check; a jog: jog.c) on the
  // machine position of a move's end: the op's (work offsets and G92
  // applied) plus the G43.1 tool length on Z. A jog beyond is refused
  // (error:15); any other move is alarm 2, which stops the machine.
  void travel(const core::Vec3& to, const core::SourceLoc& src) {
    if (failure || facts_.homing.count(src.line)) return;
    const MachineFacts::From* f = facts_.at(src.line);
    if (f == nullptr || !f->travel.soft_limits) return;
    const core::Vec3 machine = to + core::Vec3{0, 0, f->tool_length_mm};
    const int a = f->travel.beyond(machine);
    if (a < 0) return;
    const std::string what = fmt::format(
        "the machine position {}{:.4f} is outside the travel {:.3f} to 0 ($13{}={}, $20=1)",
        "XYZ"[a], machine[a], -f->travel.max[a], a, f->travel.max[a]);
    if (facts_.jogs.count(src.line)) return fail(src, 15, "the jog's target: " + what);
    failure = core::Diagnostic{
        core::Code::GrblAlarm, core::Severity::Error, src,
        fmt::format("grbl ALARM:2 (Soft limit): {}; Grbl stops and locks out every line until "
                    "a reset and $X or $H, so usina ends the run here",
                    what)};
  }

  void check_arc(const canon::Arc& a, const core::SourceLoc& src) {
    if (known_) {
      // Grbl's rule (gcode.c): the radius to the end may differ from the
      // radius to the start by 0.005 mm, or by up to 0.5 mm when that is
      // also at most 0.1 % of the radius.
      const core::Vec3 n = a.normal;
      auto in_plane = [&](const core::Vec3& v) { return v - n * core::dot(v, n); };
      const double r = core::norm(in_plane(pos_ - a.center));
      const double delta = std::fabs(core::norm(in_plane(a.to - a.center)) - r);
      if (delta > 0.005 && (delta > 0.5 || delta > 0.001 * r)) {
        fail(src, 33,
             fmt::format("the arc's end is {:.4f} mm off its circle of radius {:.4f} mm (Grbl "
                         "allows 0.005 mm, or 0.1 % of the radius up to 0.5 mm)",
                         delta, r));
      }
      arc_travel(a, src);
    }
    moved(a.to, src);
  }

  // Grbl cuts an arc into segments within $12 and checks each end.
  void arc_travel(const canon::Arc& a, const core::SourceLoc& src) {
    const MachineFacts::From* f = facts_.at(src.line);
    if (failure || f == nullptr || !f->travel.soft_limits) return;
    const core::Plane plane = std::fabs(a.normal.z) > 0.5   ? core::Plane::XY
                              : std::fabs(a.normal.y) > 0.5 ? core::Plane::ZX
                                                            : core::Plane::YZ;
    const double sweep =
        core::arc_sweep(core::in_plane(pos_, plane), core::in_plane(a.to, plane),
                        core::in_plane(a.center, plane), a.turn > 0, std::abs(a.turn));
    for (const core::Vec3& q :
         core::linearize_arc(pos_, a.to, a.center, plane, sweep, f->travel.arc_tolerance))
      travel(q, src);
  }

  void fail(const core::SourceLoc& src, int number, std::string_view detail) {
    failure = core::Diagnostic{core::Code::GrblError, core::Severity::Error, src,
                               error_message(number, detail)};
  }

  core::Vec3 pos_;
  const MachineFacts& facts_;
  bool known_ = true;
};

// The interpreter's error as Grbl's, when Grbl has a number for it.
core::Diagnostic as_grbl(core::Diagnostic d) {
  if (const int n = error_for(d.code); n > 0) {
    d.code = core::Code::GrblError;
    d.message = error_message(n, d.message);
  }
  return d;
}

}  // namespace

Prepared Runner::prepare(std::uint32_t file, const std::set<std::uint32_t>& refused,
                         std::uint32_t cut_from) const {
  const bool stop =
      c_.dialect_options.count("after_error") && c_.dialect_options.at("after_error") == "stop";
  Preparer p(dialect_, c_.dialect_options, file);
  for (std::size_t i = 0; i < lines_.size(); ++i) {
    const auto n = static_cast<std::uint32_t>(i + 1);
    if (n >= cut_from || (stop && p.failed())) {
      p.out.text += '\n';
      continue;
    }
    p.line(n, lines_[i].offset, lines_[i].text, refused.count(n) > 0);
  }
  return std::move(p.out);
}

namespace {

struct Attempt {
  CheckingSink sink;
  core::DiagnosticList diags;
  std::optional<core::Diagnostic>
      failure;  // the first line the interpreter or Grbl's geometry refused

  Attempt(const core::Vec3& start, const MachineFacts& facts) : sink(start, facts) {}
};

void run_attempt(RunContext& c, const std::vector<std::pair<int, double>>& params,
                 std::uint32_t copy, Attempt& a) {
  Interpreter interp(c.sources, c.options, a.sink, a.diags);
  for (const auto& [index, value] : params)
    interp.set_parameter(index, value);
  interp.run(copy);
  for (const core::Diagnostic& d : a.diags.all()) {
    if (d.severity == core::Severity::Error) {
      a.failure = as_grbl(d);
      break;
    }
  }
  if (a.sink.failure && (!a.failure || a.sink.failure->loc.line <= a.failure->loc.line)) {
    a.failure = a.sink.failure;
  }
}

// Decides what a run's first error does to the next copy: the line is
// refused once, and the copy run again without it; in stop mode, for an
// alarm, or past the rerun limit the program is cut there instead. An error
// with no line (or a loop that would not end) is reported with this run's
// trace. Returns whether the copy is run again.
bool refuse_or_cut(const core::Diagnostic& failure, int rerun, bool stop,
                   std::set<std::uint32_t>& refused, std::uint32_t& cut_from) {
  const std::uint32_t line = failure.loc.line;
  const bool alarm = failure.code == core::Code::GrblAlarm;
  if (line == 0 || rerun > Runner::kMaxReruns + 1) return false;
  if (stop || alarm || refused.count(line) || rerun >= Runner::kMaxReruns) {
    cut_from = line;
  } else {
    refused.insert(line);
  }
  return true;
}

}  // namespace

bool Runner::run(std::uint32_t file) {
  const core::SourceFile* source = c_.sources.get(file);
  if (source == nullptr) return false;
  split_lines(source->text());
  // Grbl's serial reader throws the mark's bytes away (above 0x7F);
  // strip_line does the same.
  skip_byte_order_mark(source->text(), file, c_.diags);
  std::set<std::uint32_t> refused;
  std::vector<core::Diagnostic> found;  // the interpreter's errors, one a rerun
  std::uint32_t cut_from = std::numeric_limits<std::uint32_t>::max();
  const bool stop = c_.dialect_options.at("after_error") == "stop";
  c_.options.start_motion = 0;  // Grbl powers up in G0
  for (int rerun = 0;; ++rerun) {
    Prepared p = prepare(file, refused, cut_from);
    const std::uint32_t copy =
        c_.sources.add(core::SourceFile::from_string(source->name(), std::move(p.text)));
    Attempt a(c_.options.start, p.facts);
    run_attempt(c_, params_, copy, a);
    if (a.failure) {
      to_file(a.failure->loc, file);
      found.push_back(*a.failure);
      if (refuse_or_cut(*a.failure, rerun, stop, refused, cut_from)) continue;
    }
    const bool ok = report_diagnostics(file, std::move(p.diags), a.diags, found);
    stream_accepted(file, copy, p.facts);
    return ok;
  }
}

void Runner::split_lines(std::string_view text) {
  lines_.clear();
  for (const LineSpan& l : grbl::split_lines(text))
    lines_.push_back({l.offset, text.substr(l.offset, l.length)});
}

// Where each op and diagnostic of the copy points: the same line of `file`.
void Runner::to_file(core::SourceLoc& loc, std::uint32_t file) const {
  loc.file = file;
  if (loc.line >= 1 && loc.line <= lines_.size()) loc.line_offset = lines_[loc.line - 1].offset;
}

// Reports, in line order, the checks' diagnostics, the last run's warnings
// and notes, and the error that ended each run; returns whether none of
// them is an error.
bool Runner::report_diagnostics(std::uint32_t file, std::vector<core::Diagnostic> diags,
                                const core::DiagnosticList& last_run,
                                const std::vector<core::Diagnostic>& found) {
  for (const core::Diagnostic& d : last_run.all()) {
    if (d.severity == core::Severity::Error || d.code == core::Code::NoProgramEnd) continue;
    diags.push_back(d);
    to_file(diags.back().loc, file);
  }
  for (const core::Diagnostic& d : found)
    diags.push_back(d);
  std::stable_sort(
      diags.begin(), diags.end(),
      [](const core::Diagnostic& x, const core::Diagnostic& y) { return x.loc.line < y.loc.line; });
  bool ok = true;
  for (core::Diagnostic& d : diags) {
    ok = ok && d.severity != core::Severity::Error;
    c_.diags.report(std::move(d));
  }
  return ok;
}

// The accepted copy once more, its ops streamed to the caller: checking
// runs keep no ops, so memory stays constant whatever the program's length.
void Runner::stream_accepted(std::uint32_t file, std::uint32_t copy, const MachineFacts& facts) {
  Attempt final_run(c_.options.start, facts);
  final_run.sink.forward = [&](const canon::Op& op) {
    canon::Op mapped = op;
    if (mapped.src.file == copy) to_file(mapped.src, file);
    c_.sink.on(mapped);
  };
  final_run.sink.downstream = &c_.sink;
  run_attempt(c_, params_, copy, final_run);
  c_.sink.finish();
}

}  // namespace usina::gcode::grbl
