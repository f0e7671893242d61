// O-word control flow: subroutines, branches and loops (LinuxCNC manual,
// "O Codes"), and Fanuc-style M98/M99 subprograms. Jumps go through the
// program index; a loop that runs more than max_loop_iterations is an error.
#include <fmt/format.h>
#include <sys/stat.h>

#include "gcode/interp/block_words.hpp"
#include "gcode/interp/interpreter.hpp"
#include "gcode/program_text.hpp"
#include "gcode/sub_name.hpp"

namespace usina::gcode {
namespace {

// A name as a diagnostic can show it: control bytes as \xNN, at most 64 bytes.
std::string printable(std::string_view name) {
  std::string out;
  if (name.size() > 64) return printable(name.substr(0, 61)) + "...";
  for (const char c : name) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte == 0x7f) {
      out += fmt::format("\\x{:02x}", byte);
    } else {
      out.push_back(c);
    }
  }
  return out;
}

}  // namespace

const ProgramIndex& Interpreter::index_of(std::uint32_t file) {
  auto it = indexes_.find(file);
  if (it == indexes_.end()) {
    it = indexes_.emplace(file, ProgramIndex::build(*sources_.get(file), file)).first;
  }
  return it->second;
}

void Interpreter::jump_to(std::uint32_t file, const OEntry& e, bool after) {
  cursor_.file = file;
  cursor_.offset = after ? e.next_line : e.offset;
  cursor_.line = after ? e.line + 1 : e.line;
}

std::optional<bool> Interpreter::condition(const OWord& o) {
  EvalError err;
  auto v = gcode::evaluate(block_, o.expr, *this, err);
  if (!v) {
    error(err.error, err.col);
    return std::nullopt;
  }
  return *v != 0.0;
}

Interpreter::Flow Interpreter::control(const OWord& o, std::uint64_t line_offset) {
  const ProgramIndex& idx = index_of(cursor_.file);
  const std::uint32_t e = idx.find(line_offset);
  if (e == kNoEntry) {
    error(core::Code::BadOWord, o.col, "O-word statement after other text on the line");
    return Flow::Error;
  }
  switch (o.kind) {
  case OKind::Sub: {
    const std::uint32_t end = idx.next_of(e, {OKind::EndSub});
    if (end == kNoEntry) {
      error(core::Code::UnclosedBlock, o.col, fmt::format("o<{}> sub has no endsub", o.label));
      return Flow::Error;
    }
    jump_to(cursor_.file, idx.at(end), true);
    return Flow::Jumped;
  }
  case OKind::EndSub:
  case OKind::Return: return leave_sub(o);
  case OKind::Call: return call(o);
  case OKind::If:
  case OKind::ElseIf:
  case OKind::Else:
  case OKind::EndIf: return branch(idx, e, o);
  case OKind::Program: return Flow::Next;
  default: return loop(idx, e, o);
  }
}

Interpreter::Flow Interpreter::branch(const ProgramIndex& idx, std::uint32_t e, const OWord& o) {
  const bool evaluate_elseif = o.kind == OKind::ElseIf && pending_elseif_ == e;
  pending_elseif_ = kNoEntry;
  if (o.kind != OKind::If && idx.prev_of(e, {OKind::If}) == kNoEntry) {
    error(core::Code::UnmatchedControl, o.col,
          fmt::format("o{} {} with no if before it", o.label, okind_name(o.kind)));
    return Flow::Error;
  }
  if (o.kind == OKind::EndIf) return Flow::Next;
  if (o.kind == OKind::If || evaluate_elseif) {
    auto c = condition(o);
    if (!c) return Flow::Error;
    if (*c) return Flow::Next;
    const std::uint32_t alt = idx.next_of(e, {OKind::ElseIf, OKind::Else, OKind::EndIf});
    if (alt == kNoEntry) {
      error(core::Code::UnclosedBlock, o.col, fmt::format("o{} if has no endif", o.label));
      return Flow::Error;
    }
    const OEntry& a = idx.at(alt);
    if (a.kind == OKind::ElseIf) pending_elseif_ = alt;
    jump_to(cursor_.file, a, a.kind != OKind::ElseIf);
    return Flow::Jumped;
  }
  // An elseif or else reached from a branch that ran: on to the endif.
  // LinuxCNC reads every elseif of the if on the way and evaluates its
  // condition all the same: an error in one stops the program.
  if (o.kind == OKind::ElseIf && !condition(o)) return Flow::Error;
  const std::uint32_t next = idx.next_of(e, {OKind::ElseIf, OKind::Else, OKind::EndIf});
  if (o.kind == OKind::ElseIf && next != kNoEntry && idx.at(next).kind == OKind::ElseIf) {
    jump_to(cursor_.file, idx.at(next), false);  // it comes here again, as skipped
    return Flow::Jumped;
  }
  const std::uint32_t end = idx.next_of(e, {OKind::EndIf});
  if (end == kNoEntry) {
    error(core::Code::UnclosedBlock, o.col,
          fmt::format("o{} {} has no endif", o.label, okind_name(o.kind)));
    return Flow::Error;
  }
  jump_to(cursor_.file, idx.at(end), true);
  return Flow::Jumped;
}

// Every backward jump of the run counts against one budget, so nested loops
// each under their own limit still end.
bool Interpreter::count_iteration() {
  return run_.count_jump("loops");
}

Interpreter::Flow Interpreter::loop_back(std::uint32_t e, const OEntry& target, bool after) {
  if (++iterations_[loop_key(e)] > options_.max_loop_iterations) {
    error(core::Code::TooManyIterations, 0,
          fmt::format("loop o{} ran more than {} times; raise the limit with --max-iterations",
                      target.label, options_.max_loop_iterations));
    return Flow::Error;
  }
  if (!count_iteration()) return Flow::Error;
  jump_to(cursor_.file, target, after);
  return Flow::Jumped;
}

// A loop's iteration count is kept under its opening entry (in this file)
// and starts again from zero each time the loop is entered anew. A loop is
// open from its opening statement until it is left; a closing statement of a
// loop that is not open is unmatched (no jump back to it).
std::uint64_t Interpreter::loop_key(std::uint32_t start) const {
  return (static_cast<std::uint64_t>(cursor_.file) << 32) | start;
}

void Interpreter::open_loop(std::uint32_t start) {
  iterations_.try_emplace(loop_key(start), 0);
}

bool Interpreter::loop_is_open(std::uint32_t start) const {
  return iterations_.count(loop_key(start)) > 0;
}

void Interpreter::forget_loop(std::uint32_t start) {
  iterations_.erase(loop_key(start));
}

Interpreter::Flow Interpreter::leave_loop(const ProgramIndex& idx, std::uint32_t e,
                                          std::uint32_t end) {
  forget_loop(e);
  jump_to(cursor_.file, idx.at(end), true);
  return Flow::Jumped;
}

Interpreter::Flow Interpreter::missing_loop_end(const OWord& o, const char* what) {
  error(core::Code::UnclosedBlock, o.col,
        fmt::format("o{} {} has no {}", o.label, okind_name(o.kind), what));
  return Flow::Error;
}

Interpreter::Flow Interpreter::unmatched_loop_end(const OWord& o, const char* what) {
  error(core::Code::UnmatchedControl, o.col,
        fmt::format("o{} {} with no {} before it", o.label, okind_name(o.kind), what));
  return Flow::Error;
}

Interpreter::Flow Interpreter::loop(const ProgramIndex& idx, std::uint32_t e, const OWord& o) {
  switch (o.kind) {
  case OKind::Do: open_loop(e); return Flow::Next;
  case OKind::While: return loop_while(idx, e, o);
  case OKind::EndWhile: {
    const std::uint32_t start = idx.prev_of(e, {OKind::While});
    if (start == kNoEntry || !loop_is_open(start)) return unmatched_loop_end(o, "while");
    return loop_back(start, idx.at(start), false);
  }
  case OKind::Repeat: return loop_repeat(idx, e, o);
  case OKind::EndRepeat: return loop_end_repeat(idx, e, o);
  case OKind::Break: return loop_break(idx, e, o);
  case OKind::Continue: {
    const std::uint32_t end = idx.next_of(e, {OKind::EndWhile, OKind::EndRepeat, OKind::While});
    if (end == kNoEntry) return missing_loop_end(o, "loop end");
    // The loop's end decides: endwhile goes back to its while, endrepeat
    // counts down, a do-while's while tests its condition.
    jump_to(cursor_.file, idx.at(end), false);
    return Flow::Jumped;
  }
  default: break;
  }
  error(core::Code::UnmatchedControl, o.col,
        fmt::format("unexpected o{} {}", o.label, okind_name(o.kind)));
  return Flow::Error;
}

// A while either opens a while-endwhile loop or closes a do-while loop.
Interpreter::Flow Interpreter::loop_while(const ProgramIndex& idx, std::uint32_t e,
                                          const OWord& o) {
  auto c = condition(o);
  if (!c) return Flow::Error;
  if (idx.at(e).ends_do) {
    const std::uint32_t start = idx.prev_of(e, {OKind::Do});
    if (start == kNoEntry || !loop_is_open(start)) return unmatched_loop_end(o, "do");
    if (*c) return loop_back(start, idx.at(start), true);
    forget_loop(start);
    return Flow::Next;
  }
  if (*c) {
    open_loop(e);
    return Flow::Next;
  }
  const std::uint32_t end = idx.next_of(e, {OKind::EndWhile});
  return end == kNoEntry ? missing_loop_end(o, "endwhile") : leave_loop(idx, e, end);
}

Interpreter::Flow Interpreter::loop_repeat(const ProgramIndex& idx, std::uint32_t e,
                                           const OWord& o) {
  EvalError err;
  auto n = gcode::evaluate(block_, o.expr, *this, err);
  if (!n) {
    error(err.error, err.col);
    return Flow::Error;
  }
  const std::uint32_t end = idx.next_of(e, {OKind::EndRepeat});
  if (end == kNoEntry) return missing_loop_end(o, "endrepeat");
  if (!(*n < 1e15)) {
    error(core::Code::BadWordValue, o.col, fmt::format("repeat [{}]: too many repeats", *n));
    return Flow::Error;
  }
  if (*n < 1.0) return leave_loop(idx, e, end);
  loops_.push_back({cursor_.file, e, static_cast<long>(*n)});
  return Flow::Next;
}

Interpreter::Flow Interpreter::loop_end_repeat(const ProgramIndex& idx, std::uint32_t e,
                                               const OWord& o) {
  const std::uint32_t start = idx.prev_of(e, {OKind::Repeat});
  if (start == kNoEntry || loops_.empty() || loops_.back().entry != start) {
    return unmatched_loop_end(o, "repeat");
  }
  if (--loops_.back().count > 0) return loop_back(start, idx.at(start), true);
  loops_.pop_back();
  forget_loop(start);
  return Flow::Next;
}

// A break leaves the innermost loop: past its end, with its count dropped.
Interpreter::Flow Interpreter::loop_break(const ProgramIndex& idx, std::uint32_t e,
                                          const OWord& o) {
  const std::uint32_t end = idx.next_of(e, {OKind::EndWhile, OKind::EndRepeat, OKind::While});
  if (end == kNoEntry) return missing_loop_end(o, "loop end");
  const OEntry& close = idx.at(end);
  if (close.kind == OKind::EndRepeat && !loops_.empty()) loops_.pop_back();
  const std::uint32_t start = close.kind == OKind::EndWhile    ? idx.prev_of(end, {OKind::While})
                              : close.kind == OKind::EndRepeat ? idx.prev_of(end, {OKind::Repeat})
                                                               : idx.prev_of(end, {OKind::Do});
  if (start != kNoEntry) forget_loop(start);
  jump_to(cursor_.file, close, true);
  return Flow::Jumped;
}

std::optional<std::uint32_t> Interpreter::load_sub_file(const std::string& name) {
  auto cached = sub_files_.find(name);
  if (cached != sub_files_.end()) return cached->second;
  // The name is only ever a file name (gcode/sub_name.hpp); call() has
  // reported why when it is not one.
  if (!subroutine_name_problem(name)) return std::nullopt;
  for (const std::string& dir : options_.subroutine_path) {
    const std::string path = (dir.empty() ? std::string(".") : dir) + "/" + name + ".ngc";

    struct stat st {};

    if (stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) continue;
    std::string err;
    auto file = core::SourceFile::open(path, err);
    if (!file) continue;
    const std::uint32_t id = sources_.add(std::move(file));
    sub_files_.emplace(name, id);
    skip_byte_order_mark(sources_.get(id)->text(), id, run_.diags());  // warned once a file
    return id;
  }
  return std::nullopt;
}

Interpreter::Flow Interpreter::call(const OWord& o) {
  std::string label = o.label;
  if (o.label_expr != kNoExpr) {
    EvalError err;
    auto v = gcode::evaluate(block_, o.label_expr, *this, err);
    if (!v) {
      error(err.error, err.col);
      return Flow::Error;
    }
    label = fmt::format("{}", *v);
  }
  if (static_cast<int>(frames_.size()) >= call_depth_limit()) {
    error(core::Code::RecursionTooDeep, o.col,
          fmt::format("o<{}> call nests deeper than {} calls", label, call_depth_limit()));
    return Flow::Error;
  }
  std::vector<double> args;
  for (const ExprRef a : o.args) {
    EvalError err;
    auto v = gcode::evaluate(block_, a, *this, err);
    if (!v) {
      error(err.error, err.col);
      return Flow::Error;
    }
    args.push_back(*v);
  }
  if (args.size() > 30) {
    error(core::Code::BadOWord, o.col, "a call takes at most 30 arguments");
    return Flow::Error;
  }
  std::uint32_t file = cursor_.file;
  std::uint32_t entry = index_of(file).sub(label);
  if (entry == kNoEntry && file != 0) {
    file = 0;  // subroutines of the main program are known everywhere
    entry = index_of(file).sub(label);
  }
  bool whole_file = false;
  if (entry == kNoEntry) {
    if (const auto ok = subroutine_name_problem(label); !ok) {
      error(core::Code::BadSubroutineName, o.col,
            fmt::format("o<{}> is not in this program and cannot be read from a file: {}",
                        printable(label), ok.error()));
      return Flow::Error;
    }
    auto loaded = load_sub_file(label);
    if (!loaded) {
      error(core::Code::UnknownSubroutine, o.col,
            fmt::format("unknown subroutine o<{}>: not in this program nor {}.ngc on the "
                        "subroutine path",
                        label, label));
      return Flow::Error;
    }
    file = *loaded;
    entry = index_of(file).sub(label);
    whole_file = entry == kNoEntry;
  }
  frames_.push_back({cursor_, label, whole_file, false, 0, 0, 0, file, std::nullopt});
  params_.push_scope();
  for (int i = 1; i <= 30; ++i) {
    params_.set(i,
                i <= static_cast<int>(args.size()) ? args[static_cast<std::size_t>(i - 1)] : 0.0);
  }
  if (whole_file) {
    cursor_ = {file, byte_order_mark_length(sources_.get(file)->text()), 1};
  } else {
    jump_to(file, index_of(file).at(entry), true);
  }
  return Flow::Jumped;
}

Interpreter::Flow Interpreter::leave_sub(const OWord& o) {
  if (frames_.empty() || frames_.back().fanuc) {
    error(core::Code::UnmatchedControl, o.col,
          fmt::format("o<{}> {} outside a subroutine call", o.label, okind_name(o.kind)));
    return Flow::Error;
  }
  value_returned_ = false;
  if (o.expr != kNoExpr) {
    EvalError err;
    auto v = gcode::evaluate(block_, o.expr, *this, err);
    if (!v) {
      error(err.error, err.col);
      return Flow::Error;
    }
    value_ = *v;
    value_returned_ = true;
  }
  params_.pop_scope();
  cursor_ = frames_.back().ret;
  if (frames_.back().autorestore) restore_modal(*frames_.back().autorestore);
  frames_.pop_back();
  return Flow::Jumped;
}

bool Interpreter::end_of_file() {
  if (!frames_.empty() && frames_.back().whole_file && frames_.back().file == cursor_.file) {
    params_.pop_scope();
    cursor_ = frames_.back().ret;
    frames_.pop_back();
    return true;
  }
  if (!frames_.empty()) {
    run_.at({cursor_.file, cursor_.line > 1 ? cursor_.line - 1 : 1, 0, 0, 0});
    error(core::Code::UnclosedBlock, 0,
          fmt::format("end of file inside subroutine o<{}>: endsub or M99 missing",
                      frames_.back().name));
    return false;
  }
  at_eof_ = true;
  return false;
}

// M98 P<program> [L<times>]: run the Fanuc-style subprogram O<program>,
// which returns at M99.
bool Interpreter::fanuc_call(const BlockWords& w) {
  if (!w.has('P'))
    return error(core::Code::MissingWord, w.mcol[kMGroupSubprogram],
                 "M98 needs P (the program number)");
  const std::string label = fmt::format("{}", w.get('P'));
  const ProgramIndex& idx = index_of(cursor_.file);
  std::uint32_t entry = kNoEntry;
  for (std::uint32_t i = 0; i < idx.entries().size(); ++i) {
    if (idx.at(i).kind == OKind::Program && idx.at(i).label == label) entry = i;
  }
  if (entry == kNoEntry) {
    return error(core::Code::UnknownSubroutine, w.col_of('P'),
                 fmt::format("no subprogram O{} in this file", label));
  }
  if (static_cast<int>(frames_.size()) >= call_depth_limit()) {
    return error(core::Code::RecursionTooDeep, w.col_of('P'),
                 fmt::format("M98 calls nest deeper than {} calls", call_depth_limit()));
  }
  std::optional<int> l;
  if (w.has('L') && !(l = whole(w, 'L', 0, kMaxToolNumber))) return false;
  const long times = l ? *l : 1;
  if (times < 1) return true;
  const OEntry& e = idx.at(entry);
  frames_.push_back({cursor_, label, false, true, times - 1, e.next_line, e.line + 1, cursor_.file,
                     std::nullopt});
  jump_to(cursor_.file, e, true);
  return true;
}

bool Interpreter::fanuc_return() {
  if (frames_.empty() || !frames_.back().fanuc) {
    // M99 in the main program: LinuxCNC's task would restart it; a trace ends.
    ended_ = true;
    return true;
  }
  Frame& f = frames_.back();
  if (f.repeats_left > 0) {
    if (!count_iteration()) return false;
    --f.repeats_left;
    cursor_ = {f.file, f.body, f.body_line};
    return true;
  }
  cursor_ = f.ret;
  frames_.pop_back();
  return true;
}

}  // namespace usina::gcode
