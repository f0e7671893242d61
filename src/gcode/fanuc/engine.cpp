// The fanuc engine's flow: blocks one by one, macro statements, loops,
// jumps and calls (docs/fanuc.md §5, §6).
#include "gcode/fanuc/engine.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "gcode/program_text.hpp"

namespace usina::gcode::fanuc {
namespace {

constexpr int kMaxLoopNesting = 3;
constexpr int kMaxMacroLevels = 4;   // G65/G66 levels on 0i/16i [16PB]
constexpr int kMaxCallNesting = 10;  // M98 + G65 on 0i-D/31i

char ascii_upper(char c) {
  return c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c;
}

// DO m / END m of a block, without evaluating it: 1 for DO, 2 for END.
// A GOTO target as a whole number; out of range values become -1 (no such
// block) rather than overflowing.
long sequence_number(double v) {
  const double r = round_half_away(v);
  return (r >= 0 && r <= 99'999'999) ? static_cast<long>(r) : -1;
}

int loop_mark(std::string_view text, int& m) {
  std::string up;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '(') {
      i = skip_comment(text, i) - 1;
    } else if (c != ' ' && c != '\t') {
      up += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    }
  }
  std::size_t at = std::string::npos;
  int kind = 0;
  if (up.rfind("WHILE", 0) == 0 || up.rfind("DO", 0) == 0) {
    at = up.rfind("DO");
    kind = 1;
    if (at != std::string::npos) at += 2;
  } else if (up.rfind("END", 0) == 0) {
    at = 3;
    kind = 2;
  }
  if (kind == 0 || at == std::string::npos) return 0;
  m = 0;
  bool any = false;
  for (; at < up.size() && std::isdigit(static_cast<unsigned char>(up[at])); ++at) {
    m = m * 10 + (up[at] - '0');
    any = true;
    if (m > 99) break;
  }
  if (!any || at != up.size()) m = -1;
  return kind;
}

}  // namespace

Engine::Engine(RunContext& c)
    : sources_(c.sources),
      options_(c.options),
      diags_(c.diags),
      stroke_(c.sink, c.options.start),
      interp_(c.sources, std::move(c.options), stroke_, c.diags, this) {
  dpi_fanuc_ = c.dialect_options["decimal_point"] == "fanuc";
  program_digits_ = c.dialect_options["program_digits"] == "8" ? 8 : 4;
  rotation_incremental_ = c.dialect_options["rotation_incremental"] == "1";
  scale_z_by_p_ = c.dialect_options["scaling_axes"] == "xyz";
  stroke_.outside_forbidden = c.dialect_options["stroke_area"] == "outside";
  g76_.shift = boring_shift_bits(c.dialect_options["boring_shift"]);
  if (const std::string& list = c.dialect_options["machine_m_codes"]; list != "all") {
    machine_m_codes_.emplace();
    for (std::size_t at = 0; at < list.size();) {
      const std::size_t comma = std::min(list.find(',', at), list.size());
      if (comma - at < 9) machine_m_codes_->insert(std::stoi(list.substr(at, comma - at)));
      at = comma + 1;
    }
  }
  polar_axes_ = polar_axes_from(c.dialect_options["polar_axes"]).value_or(PolarAxes{});
  // Not a dialect option (the command line refuses it): a test runs every
  // block down the whole road to compare with the plain-move shortcut.
  plain_move_shortcut_ = c.dialect_options.find("whole_road") == c.dialect_options.end();
  locals_.push_back(vacant_locals());
  pecks_ = {options_.peck_clearance_mm, options_.peck_clearance_mm};
  // The offset page of --offsets: the fanuc dialect's own input.
  if (auto it = c.dialect_options.find("offsets"); it != c.dialect_options.end())
    offsets_ok_ = read_offsets(it->second);
}

std::array<Value, 34> vacant_locals() {
  std::array<Value, 34> l{};
  for (Value& v : l)
    v.vacant = true;
  return l;
}

void Engine::set_parameter(int index, double value) {
  if ((index >= 100 && index <= 199) || (index >= 500 && index <= 999)) {
    common_[index] = Value{value};
  } else if (index >= 1000 && index <= 1015) {
    input_signal(index, value);
  } else if (index == 1032) {
    input_signals(value);
  } else if (index >= 5201 && index <= 5209) {
    external_[static_cast<std::size_t>(index - 5201)] = value;  // EXT, applied at the start
  } else if (index >= 1 && index <= kMaxParameter) {
    interp_.set_parameter(index, value);
  }
}

// One interface input signal from a var file: 0 or 1.
void Engine::input_signal(int index, double value) {
  const auto bit = static_cast<std::uint16_t>(1u << (index - 1000));
  if (value != 0 && value != 1) {
    diags_.report({core::Code::VarFileLineSkipped,
                   core::Severity::Warning,
                   {},
                   fmt::format("--var-file #{} = {}: an input signal is 0 or 1; left 0", index,
                               word_number(value))});
    return;
  }
  inputs_ = static_cast<std::uint16_t>(value == 1 ? inputs_ | bit : inputs_ & ~bit);
}

// #1032 from a var file: the 16 signals as one whole number.
void Engine::input_signals(double value) {
  if (!(value >= 0 && value <= 65535 && value == std::floor(value))) {
    diags_.report({core::Code::VarFileLineSkipped,
                   core::Severity::Warning,
                   {},
                   fmt::format("--var-file #1032 = {}: the 16 input signals make a whole number "
                               "from 0 to 65535; left as they were",
                               word_number(value))});
    return;
  }
  inputs_ = static_cast<std::uint16_t>(value);
}

// #500-#999 as they stand; a vacant one has no line (a var file holds
// numbers only).
// The interpreter's modes, with what this front end keeps itself: the
// length offset's register (the interpreter is given its value, G43.1) and
// the transformations and polar modes that move the frame.
std::optional<RunModes> Engine::modes() const {
  RunModes m = run_modes(interp_.state());
  if (length_sign_ == 0) m.length_h = -1;
  // G44 (a negative offset) is not written back: -2 refuses the restart.
  else
    m.length_h = length_sign_ > 0 ? static_cast<int>(std::clamp(h_register_, 0L, 99'999'999L)) : -2;
  m.frame_moved = m.frame_moved || xf_.active() || polar_;
  m.offsets_written = m.offsets_written || offsets_written_;
  return m;
}

std::optional<std::vector<VarFileEntry>> Engine::persistent_variables() const {
  std::vector<VarFileEntry> out;
  for (const auto& [index, value] : common_) {
    if (index >= 500 && index <= 999 && !value.vacant)
      out.push_back({static_cast<int>(index), value.v});
  }
  return out;
}

// A position in a block's text is a column of its line: the text is the
// file's own, comments and all.
core::SourceLoc Engine::loc_of(const TapeBlock& b, std::size_t pos) const {
  return {b.loc.file, b.loc.line, b.loc.col + static_cast<std::uint32_t>(pos), 1,
          b.loc.line_offset};
}

bool Engine::error(core::Code code, const TapeBlock& b, std::size_t pos, std::string message) {
  diags_.report({code, core::Severity::Error, loc_of(b, pos), std::move(message)});
  failed_ = true;
  return false;
}

void Engine::warn(core::Code code, const TapeBlock& b, std::size_t pos, std::string message) {
  diags_.report({code, core::Severity::Warning, loc_of(b, pos), std::move(message)});
}

bool Engine::macro_error(const MacroReader& r, const TapeBlock& b) {
  return error(r.error().code, b, r.error().pos, r.error().message);
}

bool Engine::run(std::uint32_t file) {
  core::SourceFile* f = sources_.get(file);
  if (f == nullptr || !offsets_ok_) return false;
  main_file_ = file;
  main_start_ = tape_.add_file(file, f->text(), skip_byte_order_mark(f->text(), file, diags_));
  pc_ = main_start_;
  if (const TapeBlock first = tape_.cut(main_start_); !first.end) {
    // Fanuc's power-on return mode is G98 (LinuxCNC starts in G99).
    hand(first, {{'G', 98}});
  }
  apply_start_external();
  while (!done_ && !failed_ && !interp_.failed() && !interp_.ended()) {
    step();
    if (stroke_violation()) break;
    if (stroke_.stopped()) failed_ = true;  // the operation budget ran out
  }
  const bool ok = !failed_ && !interp_.failed();
  interp_.finish();
  return !stroke_violation() && ok && !interp_.failed();
}

// An O block ends the program that runs: the main program once a block
// with words or its own O block was read (a leader of comments before the
// O block belongs to it), a called one at any O block but its own.
bool Engine::ends_program(const TapeBlock& b) {
  if (b.program < 0) return false;
  if (!frames_.empty()) return !(b.at == frames_.back().start);
  return main_started_;
}

bool Engine::end_of_program(const TapeBlock& end) {
  if (!read_any_) {
    done_ = true;
    diags_.report({core::Code::NoProgramEnd,
                   core::Severity::Warning,
                   {main_file_, 1, 0, 0, 0},
                   "the program is empty"});
    return true;
  }
  const TapeBlock last = tape_.cut(last_at_);
  if (parameter_mode_) {
    return error(core::Code::UnclosedBlock, last, 0,
                 "the program ends in parameter input mode: G10 L50 without G11");
  }
  if (!frames_.empty()) {
    return error(core::Code::UnclosedBlock, last, 0,
                 "the subprogram ends without M99 (Fanuc: it would run into the next program)");
  }
  done_ = true;
  if (!end.end || !end.closed) {
    diags_.report({core::Code::NoProgramEnd, core::Severity::Warning, loc_of(last, 0),
                   "the program ends without M02, M30 or '%'; taken as its end"});
  }
  return true;
}

bool Engine::step() {
  tape_.cut(pc_, block_);
  const TapeBlock& b = block_;
  if (b.end || ends_program(b)) return end_of_program(b);
  pc_ = b.next;
  last_at_ = b.at;
  read_any_ = true;
  if (frames_.empty() && (b.program >= 0 || !b.text.empty())) main_started_ = true;
  core::SourceFile* file = sources_.get(b.loc.file);
  // The text behind the reader may leave memory (it comes back on a jump).
  file->release_before(b.loc.line_offset);
  const std::string_view src = file->text();
  const std::size_t start = b.loc.line_offset + b.col - 1;
  if (auto length = check_block_length(src.substr(start, b.length),
                                       {b.loc.file, b.loc.line, b.col, 1, b.loc.line_offset});
      !length) {
    diags_.report(std::move(length.error()));
    failed_ = true;
    return false;
  }
  if (b.program >= 0) o_ = static_cast<double>(b.program);
  if (b.deleted && options_.block_delete) return true;
  if (parameter_mode_) return parameter_block(b);
  if (b.sequence >= 0) n_ = static_cast<double>(b.sequence);
  if (b.text.empty()) return true;
  const char c = ascii_upper(b.text[0]);
  const char second = b.text.size() > 1 ? ascii_upper(b.text[1]) : '\0';
  if (c == '#' || c == 'I' || c == 'W' || c == 'E' || ((c == 'D' || c == 'G') && second == 'O')) {
    return statement(b);
  }
  return nc_block(b);
}

bool Engine::statement(const TapeBlock& b) {
  MacroReader r(b.text, *this);
  if (r.peek() == '#') return assignment(r, b, true);
  if (r.keyword("GOTO")) {
    auto n = r.expression();
    if (!n) return macro_error(r, b);
    if (!r.at_end()) return error(core::Code::MacroFormat, b, r.pos(), "text after GOTO n");
    return goto_block(sequence_number(n->v), b, 0);
  }
  if (r.keyword("IF")) {
    auto cond = r.condition();
    if (!cond) return macro_error(r, b);
    if (r.keyword("GOTO")) {
      const std::size_t at = r.pos();
      auto n = r.expression();
      if (!n) return macro_error(r, b);
      if (!r.at_end()) return error(core::Code::MacroFormat, b, r.pos(), "text after GOTO n");
      return *cond ? goto_block(sequence_number(n->v), b, at) : true;
    }
    if (r.keyword("THEN")) {
      if (r.peek() != '#')
        return error(core::Code::MacroFormat, b, r.pos(), "THEN takes an assignment #i = ..");
      return assignment(r, b, *cond);
    }
    return error(core::Code::MacroFormat, b, r.pos(), "IF [..] needs GOTO n or THEN #i = ..");
  }
  if (r.keyword("WHILE")) {
    auto cond = r.condition();
    if (!cond) return macro_error(r, b);
    return while_do(r, b, cond);
  }
  if (r.peek() == 'D') return while_do(r, b, true);
  if (r.keyword("END")) return end_loop(r, b);
  return nc_block(b);
}

bool Engine::assignment(MacroReader& r, const TapeBlock& b, bool run) {
  const std::size_t at = r.pos();
  auto index = r.variable_number();
  if (!index) return macro_error(r, b);
  if (!r.accept('=')) return error(core::Code::MacroFormat, b, r.pos(), "expected '=' after #n");
  auto v = r.expression();
  if (!v) return macro_error(r, b);
  if (r.relation_used()) {
    return error(core::Code::MacroFormat, b, at,
                 "a relation (EQ NE GT GE LT LE) cannot be stored in a variable");
  }
  if (!r.at_end()) {
    return error(core::Code::MacroFormat, b, r.pos(),
                 "a macro statement stands alone in its block (Fanuc alarm 114)");
  }
  if (!run) return true;
  return write(*index, *v, b, at);
}

bool Engine::count_jump(const TapeBlock& b) {
  if (++total_jumps_ <= options_.max_total_iterations) return true;
  return error(core::Code::TooManyIterations, b, 0,
               fmt::format("the program's loops and jumps ran more than {} times; raise the "
                           "limit with --max-total-iterations",
                           options_.max_total_iterations));
}

// The END m of the loop that DO m opens, searched once per DO block (the
// program's blocks up to its end).
std::optional<Engine::LoopEnd> Engine::find_end(const TapeBlock& do_block, int m) {
  if (auto it = loop_ends_.find(do_block.at.key()); it != loop_ends_.end()) return it->second;
  std::vector<int> open;
  TapeBlock k = tape_.cut(do_block.next);
  for (; !k.end && k.program < 0; k = tape_.cut(k.next)) {
    int mk = 0;
    const int kind = loop_mark(k.text, mk);
    if (kind == 1) {
      open.push_back(mk);
    } else if (kind == 2) {
      if (open.empty()) {
        if (mk == m) return loop_ends_[do_block.at.key()] = LoopEnd{k.at, k.next};
        error(core::Code::BadLoop, k, 0,
              fmt::format("END {} closes a loop opened as DO {}: loops overlap (Fanuc alarm 124)",
                          mk, m));
        return std::nullopt;
      }
      if (open.back() != mk) {
        error(core::Code::BadLoop, k, 0,
              fmt::format("END {} closes DO {}: loops overlap (Fanuc alarm 124)", mk, open.back()));
        return std::nullopt;
      }
      open.pop_back();
    }
  }
  error(core::Code::BadLoop, do_block, 0,
        fmt::format("DO {} has no END {} (Fanuc alarm 124)", m, m));
  return std::nullopt;
}

bool Engine::while_do(MacroReader& r, const TapeBlock& b, std::optional<bool> cond) {
  if (!r.keyword("DO")) return error(core::Code::MacroFormat, b, r.pos(), "WHILE [..] needs DO m");
  const std::size_t at = r.pos();
  auto m = r.expression();
  if (!m) return macro_error(r, b);
  if (!r.at_end()) return error(core::Code::MacroFormat, b, r.pos(), "text after DO m");
  if (m->v != 1 && m->v != 2 && m->v != 3)
    return error(core::Code::BadLoop, b, at, "DO takes 1, 2 or 3 (Fanuc alarm 126)");
  const auto end = find_end(b, static_cast<int>(m->v));
  if (!end) return false;
  std::vector<Loop>& active = loops();
  const bool running = !active.empty() && active.back().do_block == b.at;
  if (!*cond) {
    if (running) active.pop_back();
    pc_ = end->after;
    return true;
  }
  if (!running) {
    if (static_cast<int>(active.size()) >= kMaxLoopNesting)
      return error(core::Code::BadLoop, b, 0, "WHILE loops nest deeper than 3 (Fanuc alarm 126)");
    active.push_back({b.at, end->end_block});
    loop_runs_.erase(b.at.key());
  }
  return true;
}

bool Engine::end_loop(MacroReader& r, const TapeBlock& b) {
  auto m = r.expression();
  if (!m) return macro_error(r, b);
  std::vector<Loop>& active = loops();
  if (active.empty() || !(active.back().end_block == b.at)) {
    return error(core::Code::BadLoop, b, 0,
                 fmt::format("END {} without its WHILE .. DO {} (Fanuc alarm 124)", m->v, m->v));
  }
  if (++loop_runs_[active.back().do_block.key()] > options_.max_loop_iterations) {
    return error(core::Code::TooManyIterations, b, 0,
                 fmt::format("the loop ran more than {} times; raise the limit with "
                             "--max-iterations",
                             options_.max_loop_iterations));
  }
  if (!count_jump(b)) return false;
  pc_ = active.back().do_block;
  return true;
}

// Block N`n` of the running program: from `from` to the program's end,
// then from its start up to `from`.
std::optional<TapePos> Engine::find_sequence(long n, TapePos from, TapePos start) const {
  for (TapeBlock k = tape_.cut(from); !k.end && (k.program < 0 || k.at == start);
       k = tape_.cut(k.next)) {
    if (k.sequence == n) return k.at;
  }
  for (TapeBlock k = tape_.cut(start); !k.end && k.at < from; k = tape_.cut(k.next)) {
    if (k.sequence == n) return k.at;
  }
  return std::nullopt;
}

// Where GOTO n of block b leads, searched once per site (and program).
const Engine::Jump& Engine::jump(long n, const TapeBlock& b) {
  const TapePos start = program_start();
  const JumpKey key{b.at.key(), start.key(), n};
  if (auto it = jumps_.find(key); it != jumps_.end()) return it->second;
  Jump j;
  if (n >= 1 && n <= 99999) j.target = find_sequence(n, b.next, start);
  if (j.target) {
    std::vector<std::uint64_t> open;
    for (TapeBlock k = tape_.cut(start); !k.end && k.at < *j.target; k = tape_.cut(k.next)) {
      int m = 0;
      const int kind = loop_mark(k.text, m);
      if (kind == 1) open.push_back(k.at.key());
      if (kind == 2 && !open.empty()) open.pop_back();
    }
    j.open_loops = std::move(open);
  }
  return jumps_[key] = std::move(j);
}

bool Engine::goto_block(long n, const TapeBlock& b, std::size_t pos) {
  const Jump& j = jump(n, b);
  if (!j.target) {
    return error(core::Code::UnknownBlockNumber, b, pos,
                 fmt::format("GOTO {}: no block N{} in this program (Fanuc alarm 128)", n, n));
  }
  const TapePos target = *j.target;
  // The loops around the target must be running: no jump into a loop.
  std::vector<Loop>& active = loops();
  for (std::uint64_t d : j.open_loops) {
    bool running = false;
    for (const Loop& l : active)
      running = running || l.do_block.key() == d;
    if (!running && d != target.key()) {
      return error(core::Code::BadLoop, b, pos,
                   fmt::format("GOTO {} jumps into a WHILE loop (Fanuc alarm 128)", n));
    }
  }
  while (!active.empty() && (target <= active.back().do_block || active.back().end_block < target))
    active.pop_back();
  if (target <= b.at && !count_jump(b)) return false;
  pc_ = target;
  return true;
}

std::optional<TapePos> Engine::find_program(long number) {
  if (auto at = tape_.program(number)) return at;
  namespace fs = std::filesystem;
  const std::string names[] = {fmt::format("O{:04}", number),    fmt::format("O{}", number),
                               fmt::format("O{:04}.nc", number), fmt::format("O{}.nc", number),
                               fmt::format("{:04}.nc", number),  fmt::format("{}.nc", number),
                               fmt::format("o{:04}.nc", number), fmt::format("o{}.nc", number)};
  for (const std::string& dir : options_.subroutine_path) {
    for (const std::string& name : names) {
      const fs::path p = fs::path(dir) / name;
      std::error_code ec;
      if (!fs::is_regular_file(p, ec)) continue;
      std::string why;
      auto file = core::SourceFile::open(p.string(), why);
      if (!file) continue;
      const std::uint32_t id = sources_.add(std::move(file));
      const std::string_view text = sources_.get(id)->text();
      const TapePos first = tape_.add_file(id, text, skip_byte_order_mark(text, id, diags_));
      if (auto at = tape_.program(number)) return at;
      if (!tape_.cut(first).end) return first;
    }
  }
  return std::nullopt;
}

bool Engine::call(long program, long times, bool macro, const std::array<Value, 34>* args,
                  const TapeBlock& b, std::size_t pos, bool modal) {
  const std::optional<TapePos> o = find_program(program);
  if (!o) {
    return error(core::Code::UnknownSubroutine, b, pos,
                 fmt::format("no program O{:04} in this file or the subroutine path (Fanuc "
                             "alarm 078)",
                             program));
  }
  int levels = 0;
  for (const Frame& f : frames_)
    levels += f.macro ? 1 : 0;
  if (static_cast<int>(frames_.size()) >= std::min(kMaxCallNesting, options_.max_call_depth) ||
      (macro && levels >= kMaxMacroLevels)) {
    return error(
        core::Code::RecursionTooDeep, b, pos,
        fmt::format("calls nest deeper than {} (Fanuc alarm 077)",
                    macro && levels >= kMaxMacroLevels ? kMaxMacroLevels : kMaxCallNesting));
  }
  if (times < 1) return true;
  Frame f;
  f.ret = pc_;
  f.start = *o;
  const TapeBlock head = tape_.cut(*o);
  f.body = head.program >= 0 ? head.next : *o;
  f.repeats_left = times - 1;
  f.macro = macro;
  f.modal_call = modal;
  frames_.push_back(f);
  if (macro) locals_.push_back(args != nullptr ? *args : vacant_locals());
  pc_ = f.body;
  return true;
}

// M99 [P n]: back to the caller (or again, with repeats left).
bool Engine::give_back(long sequence, const TapeBlock& b, std::size_t pos) {
  if (frames_.empty()) {
    if (sequence >= 0) return goto_block(sequence, b, pos);
    warn(core::Code::NoProgramEnd, b, pos,
         "M99 in the main program: a control starts it again; the trace ends here");
    done_ = true;
    return true;
  }
  Frame& f = frames_.back();
  if (f.repeats_left > 0) {
    if (!count_jump(b)) return false;
    --f.repeats_left;
    f.loops.clear();
    pc_ = f.body;
    return true;
  }
  const TapePos ret = f.ret;
  if (f.macro) locals_.pop_back();
  frames_.pop_back();
  pc_ = ret;
  if (sequence < 0) return true;
  const JumpKey key{b.at.key(), ret.key(), sequence};
  auto it = returns_.find(key);
  if (it == returns_.end())
    it = returns_.emplace(key, find_sequence(sequence, ret, program_start())).first;
  if (it->second) {
    pc_ = *it->second;
    return true;
  }
  return error(core::Code::UnknownBlockNumber, b, pos,
               fmt::format("M99 P{}: no block N{} in the calling program", sequence, sequence));
}

}  // namespace usina::gcode::fanuc
