// The fanuc engine's flow: blocks one by one, macro statements, loops,
// jumps and calls (docs/fanuc.md §5, §6).
#include "gcode/dialects/fanuc_engine.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include <fmt/format.h>

#include "gcode/program_text.hpp"

namespace usina::gcode::fanuc {
namespace {

constexpr int kMaxLoopNesting = 3;
constexpr int kMaxMacroLevels = 4;   // G65/G66 levels on 0i/16i [16PB]
constexpr int kMaxCallNesting = 10;  // M98 + G65 on 0i-D/31i

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
  polar_axes_ = polar_axes_from(c.dialect_options["polar_axes"]).value_or(PolarAxes{});
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
  } else if (index >= 5201 && index <= 5209) {
    external_[static_cast<std::size_t>(index - 5201)] = value;  // EXT, applied at the start
  } else if (index >= 1 && index <= kMaxParameter) {
    interp_.set_parameter(index, value);
  }
}

// #500-#999 as they stand; a vacant one has no line (a var file holds
// numbers only).
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
  const std::string_view src = sources_.get(b.file)->text();
  const auto col = static_cast<std::uint32_t>(b.text.data() - src.data() - b.line_offset + pos + 1);
  return {b.file, b.line, col, 1, b.line_offset};
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
  const core::SourceFile* f = sources_.get(file);
  if (f == nullptr || !offsets_ok_) return false;
  main_file_ = file;
  tape_.add_file(file, f->text(), skip_byte_order_mark(f->text(), file, diags_));
  main_end_ = tape_.size() > 0 ? tape_.program_end(0) : 0;
  if (tape_.size() > 0) {
    // Fanuc's power-on return mode is G98 (LinuxCNC starts in G99).
    hand(tape_.at(0), {{'G', 98}});
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

bool Engine::end_of_program() {
  if (tape_.size() == 0) {
    done_ = true;
    diags_.report({core::Code::NoProgramEnd,
                   core::Severity::Warning,
                   {main_file_, 1, 0, 0, 0},
                   "the program is empty"});
    return true;
  }
  const TapeBlock& last = tape_.at(pc_ == 0 ? 0 : pc_ - 1);
  if (parameter_mode_) {
    return error(core::Code::UnclosedBlock, last, 0,
                 "the program ends in parameter input mode: G10 L50 without G11");
  }
  if (!frames_.empty()) {
    return error(core::Code::UnclosedBlock, last, 0,
                 "the subprogram ends without M99 (Fanuc: it would run into the next program)");
  }
  done_ = true;
  if (!tape_.closed(pc_ == 0 ? 0 : pc_ - 1) || pc_ < tape_.size()) {
    diags_.report({core::Code::NoProgramEnd, core::Severity::Warning, loc_of(last, 0),
                   "the program ends without M02, M30 or '%'; taken as its end"});
  }
  return true;
}

bool Engine::step() {
  const std::size_t end = frames_.empty() ? main_end_ : frames_.back().end;
  if (pc_ >= end || pc_ >= tape_.size()) return end_of_program();
  const TapeBlock& b = tape_.at(pc_);
  ++pc_;
  const std::string_view src = sources_.get(b.file)->text();
  const std::size_t start = b.line_offset + b.col - 1;
  if (auto too_long =
          block_too_long(src.substr(start, b.length), {b.file, b.line, b.col, 1, b.line_offset})) {
    diags_.report(std::move(*too_long));
    failed_ = true;
    return false;
  }
  if (b.program >= 0) o_ = static_cast<double>(b.program);
  if (b.deleted && options_.block_delete) return true;
  if (parameter_mode_) return parameter_block(b);
  if (b.sequence >= 0) n_ = static_cast<double>(b.sequence);
  if (b.text.empty()) return true;
  const char c = static_cast<char>(std::toupper(static_cast<unsigned char>(b.text[0])));
  const char second = b.text.size() > 1
                          ? static_cast<char>(std::toupper(static_cast<unsigned char>(b.text[1])))
                          : '\0';
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

std::size_t Engine::find_end(std::size_t do_block, int m, const TapeBlock& b) {
  const std::size_t end = tape_.program_end(do_block);
  std::vector<int> open;
  for (std::size_t k = do_block + 1; k < end; ++k) {
    int mk = 0;
    const int kind = loop_mark(tape_.at(k).text, mk);
    if (kind == 1) {
      open.push_back(mk);
    } else if (kind == 2) {
      if (open.empty()) {
        if (mk == m) return k;
        error(core::Code::BadLoop, tape_.at(k), 0,
              fmt::format("END {} closes a loop opened as DO {}: loops overlap (Fanuc alarm 124)",
                          mk, m));
        return Tape::npos;
      }
      if (open.back() != mk) {
        error(core::Code::BadLoop, tape_.at(k), 0,
              fmt::format("END {} closes DO {}: loops overlap (Fanuc alarm 124)", mk, open.back()));
        return Tape::npos;
      }
      open.pop_back();
    }
  }
  error(core::Code::BadLoop, b, 0, fmt::format("DO {} has no END {} (Fanuc alarm 124)", m, m));
  return Tape::npos;
}

bool Engine::while_do(MacroReader& r, const TapeBlock& b, std::optional<bool> cond) {
  if (!r.keyword("DO")) return error(core::Code::MacroFormat, b, r.pos(), "WHILE [..] needs DO m");
  const std::size_t at = r.pos();
  auto m = r.expression();
  if (!m) return macro_error(r, b);
  if (!r.at_end()) return error(core::Code::MacroFormat, b, r.pos(), "text after DO m");
  if (m->v != 1 && m->v != 2 && m->v != 3)
    return error(core::Code::BadLoop, b, at, "DO takes 1, 2 or 3 (Fanuc alarm 126)");
  const std::size_t here = pc_ - 1;
  const std::size_t end = find_end(here, static_cast<int>(m->v), b);
  if (end == Tape::npos) return false;
  std::vector<Loop>& active = loops();
  const bool running = !active.empty() && active.back().do_block == here;
  if (!*cond) {
    if (running) active.pop_back();
    pc_ = end + 1;
    return true;
  }
  if (!running) {
    if (static_cast<int>(active.size()) >= kMaxLoopNesting)
      return error(core::Code::BadLoop, b, 0, "WHILE loops nest deeper than 3 (Fanuc alarm 126)");
    active.push_back({here, end});
    loop_runs_.erase(here);
  }
  return true;
}

bool Engine::end_loop(MacroReader& r, const TapeBlock& b) {
  auto m = r.expression();
  if (!m) return macro_error(r, b);
  std::vector<Loop>& active = loops();
  const std::size_t here = pc_ - 1;
  if (active.empty() || active.back().end_block != here) {
    return error(core::Code::BadLoop, b, 0,
                 fmt::format("END {} without its WHILE .. DO {} (Fanuc alarm 124)", m->v, m->v));
  }
  if (++loop_runs_[active.back().do_block] > options_.max_loop_iterations) {
    return error(core::Code::TooManyIterations, b, 0,
                 fmt::format("the loop ran more than {} times; raise the limit with "
                             "--max-iterations",
                             options_.max_loop_iterations));
  }
  if (!count_jump(b)) return false;
  pc_ = active.back().do_block;
  return true;
}

bool Engine::goto_block(long n, const TapeBlock& b, std::size_t pos) {
  const std::size_t here = pc_ - 1;
  const std::size_t start = frames_.empty() ? 0 : tape_.program_start(here);
  const std::size_t end = frames_.empty() ? main_end_ : frames_.back().end;
  std::size_t target = Tape::npos;
  for (std::size_t k = here + 1; k < end && target == Tape::npos; ++k)
    if (tape_.at(k).sequence == n) target = k;
  for (std::size_t k = start; k <= here && target == Tape::npos; ++k)
    if (tape_.at(k).sequence == n) target = k;
  if (n < 1 || n > 99999 || target == Tape::npos) {
    return error(core::Code::UnknownBlockNumber, b, pos,
                 fmt::format("GOTO {}: no block N{} in this program (Fanuc alarm 128)", n, n));
  }
  // The loops around the target must be running: no jump into a loop.
  std::vector<std::size_t> open;
  for (std::size_t k = start; k < target; ++k) {
    int m = 0;
    const int kind = loop_mark(tape_.at(k).text, m);
    if (kind == 1) open.push_back(k);
    if (kind == 2 && !open.empty()) open.pop_back();
  }
  std::vector<Loop>& active = loops();
  for (std::size_t d : open) {
    bool running = false;
    for (const Loop& l : active)
      running = running || l.do_block == d;
    if (!running && d != target) {
      return error(core::Code::BadLoop, b, pos,
                   fmt::format("GOTO {} jumps into a WHILE loop (Fanuc alarm 128)", n));
    }
  }
  while (!active.empty() && (target <= active.back().do_block || target > active.back().end_block))
    active.pop_back();
  if (target <= here && !count_jump(b)) return false;
  pc_ = target;
  return true;
}

std::size_t Engine::find_program(long number) {
  const std::size_t at = tape_.program(number);
  if (at != Tape::npos) return at;
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
      const std::size_t first = tape_.add_file(id, text, skip_byte_order_mark(text, id, diags_));
      const std::size_t o = tape_.program(number);
      if (o != Tape::npos) return o;
      if (first < tape_.size()) return first;
    }
  }
  return Tape::npos;
}

bool Engine::call(long program, long times, bool macro, const std::array<Value, 34>* args,
                  const TapeBlock& b, std::size_t pos, bool modal) {
  const std::size_t o = find_program(program);
  if (o == Tape::npos) {
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
  f.body = tape_.at(o).program >= 0 ? o + 1 : o;
  f.end = tape_.program_end(o);
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
  const std::size_t ret = f.ret;
  if (f.macro) locals_.pop_back();
  frames_.pop_back();
  pc_ = ret;
  if (sequence < 0) return true;
  const std::size_t start = frames_.empty() ? 0 : tape_.program_start(ret - 1);
  const std::size_t end = frames_.empty() ? main_end_ : frames_.back().end;
  for (std::size_t k = ret; k < end; ++k) {
    if (tape_.at(k).sequence == sequence) {
      pc_ = k;
      return true;
    }
  }
  for (std::size_t k = start; k < ret; ++k) {
    if (tape_.at(k).sequence == sequence) {
      pc_ = k;
      return true;
    }
  }
  return error(core::Code::UnknownBlockNumber, b, pos,
               fmt::format("M99 P{}: no block N{} in the calling program", sequence, sequence));
}

}  // namespace usina::gcode::fanuc
