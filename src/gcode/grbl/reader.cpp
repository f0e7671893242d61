// Grbl's side of each line (grbl/reader.hpp): what Grbl's protocol loop,
// gc_execute_line and system_execute_line do with a line, up to the moves.
#include "gcode/grbl/reader.hpp"

#include <utility>

#include <fmt/format.h>

#include "gcode/program_text.hpp"

namespace usina::gcode::grbl {
namespace {

// Grbl's LINE_BUFFER_SIZE (config.h) less its terminator.
std::size_t line_length(const OptionValues& o) {
  const auto it = o.find("line_buffer");
  return it == o.end() ? kMaxLineLength : std::stoul(it->second) - 1;
}

}  // namespace

LineReader::LineReader(const Dialect& d, const OptionValues& options, std::uint32_t file)
    : codes_(code_index(d)),
      options_(options),
      file_(file),
      max_length_(line_length(options)),
      straight_lines_(options.find("whole_road") == options.end()),
      travel_(Travel::of(settings_)) {}

LineKind LineReader::read(std::uint32_t n, std::uint64_t offset, std::string_view text,
                          std::vector<core::Diagnostic>& diags) {
  diags_ = &diags;
  loc_ = {file_, n, 1, 0, offset};
  if (now_.ended) return after_end(text);
  if (auto length = check_block_length(text, loc_); !length) {
    diags.push_back(std::move(length.error()));
    return LineKind::Refused;
  }
  line_ = text;
  if (straight(text)) return LineKind::Run;
  // Most other lines are words and blanks, read straight from the line;
  // the others are stripped as Grbl's line reader strips them first.
  words_of_line_ = true;
  std::size_t kept = 0;
  const bool plain = read_plain_words(text, words_, kept);
  if (!plain) {
    strip_line(text, stripped_);
    warnings_of_the_line();
    const std::string& s = stripped_.text;
    if (s.empty() || s == "%") return LineKind::Nothing;
    kept = s.size();
  }
  if (kept > max_length_) {
    return fail({11, 1,
                 fmt::format("{} characters after blanks and comments are removed; Grbl holds {}",
                             kept, max_length_)});
  }
  next_ = now_;
  next_settings_.reset();
  facts_ = {travel_, now_.modal.tool_length_mm, false, false};
  if (plain) return block();
  if (stripped_.text[0] == '$') return system();
  if (auto f = read_words(stripped_.text, stripped_.cols, words_); !f) return fail(f.error());
  return block();
}

// Most lines: one plain move (read_straight_line) that Grbl's checks let
// by (check_plain_move), handed as the move; its words are read only if
// the interpreter asks for them (handed()). False, with nothing changed
// that stands, for any other line: the general road reads it (a line over
// Grbl's length too, for its error).
bool LineReader::straight(std::string_view text) {
  std::size_t kept = 0;
  std::uint32_t col = 0;
  if (!straight_lines_ || !read_straight_line(text, move_, kept, col) || kept > max_length_)
    return false;
  next_ = now_;
  Accepted acc;
  if (!check_plain_move(move_, next_.modal, acc) || keeps_modes(acc)) return false;
  next_settings_.reset();
  facts_ = {travel_, now_.modal.tool_length_mm, false, false};
  append_kept_modes(acc);  // none kept: the kept motion ends if the line moves
  plain_ = true;
  words_of_line_ = false;
  handed_made_ = false;
  block_col_ = col;
  return true;
}

// A line after M2/M30: nothing to run, a warning for the first that holds
// more than '%'.
LineKind LineReader::after_end(std::string_view text) {
  strip_line(text, stripped_);
  const std::string& s = stripped_.text;
  if (!s.empty() && s != "%" && !warned_after_end_) {
    warn(core::Code::TextAfterProgramEnd, 1,
         "lines after M2/M30: Grbl goes on reading them, usina's trace ends at the program end");
    warned_after_end_ = true;
  }
  return LineKind::Nothing;
}

void LineReader::accept() {
  now_ = next_;
  if (next_settings_) {
    settings_ = std::move(*next_settings_);
    next_settings_.reset();
    travel_ = Travel::of(settings_);
  }
}

void LineReader::warnings_of_the_line() {
  const StrippedLine& s = stripped_;
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
}

// A G-code line, its words read: Grbl's checks on a copy of its modal
// state, then Grbl's words for the interpreter, as Grbl read them (N is
// Grbl's line number, no word of the block). A plain move goes as the move,
// unless the modes a jog kept go with it; its words are made if asked.
LineKind LineReader::block() {
  Accepted acc;
  plain_ = check_plain_block(words_, next_.modal, acc, move_);
  if (!plain_) {
    if (auto f = check_block_whole(codes_, options_, words_, next_.modal, acc); !f)
      return fail(f.error());
  }
  block_col_ = words_.front().col;
  if (keeps_modes(acc)) plain_ = false;
  handed_made_ = false;
  if (!plain_) handed();
  append_kept_modes(acc);
  if (acc.program_end) next_.ended = true;
  facts_.tool_length_mm = next_.modal.tool_length_mm;
  return LineKind::Run;
}

const HandedBlock& LineReader::handed() {
  if (handed_made_) return handed_;
  if (!words_of_line_) {
    std::size_t kept = 0;
    read_plain_words(line_, words_, kept);  // a straight line: plain
    words_of_line_ = true;
  }
  handed_.clear();
  for (const Word& w : words_) {
    if (w.letter != 'N') handed_.words.push_back({w.letter, w.value, w.col});
  }
  handed_made_ = true;
  return handed_;
}

// Whether the line takes modes a jog or `$H` changed along.
bool LineReader::keeps_modes(const Accepted& acc) const {
  const Restore& r = next_.restore;
  return r.modes || (acc.uses_motion && r.motion);
}

// The words the interpreter's line needs besides Grbl's: the modes a jog or
// `$H` changed.
void LineReader::append_kept_modes(const Accepted& acc) {
  Restore& r = next_.restore;
  if (!keeps_modes(acc)) {
    if (acc.uses_motion || acc.sets_motion) r.motion = false;
    return;
  }
  const double per_unit = now_.modal.inch ? 25.4 : 1.0;
  if (r.modes) {
    const Modal& p = r.before;
    if (!acc.sets_distance) handed_.add('G', p.incremental ? 91 : 90);
    if (!acc.sets_feed_mode) handed_.add('G', p.inverse_time ? 93 : 94);
    if (!acc.sets_feed) handed_.add('F', p.inverse_time ? p.feed_mm : p.feed_mm / per_unit);
    r.modes = false;
  }
  if (acc.uses_motion && r.motion) handed_.add('G', r.before.motion / 10.0);
  if (acc.uses_motion || acc.sets_motion) r.motion = false;
}

// A `$` line, on a copy of the settings.
LineKind LineReader::system() {
  next_settings_ = settings_;
  SystemResult r =
      system_command(codes_, options_, stripped_.text, stripped_.cols, now_.modal, *next_settings_);
  for (std::string& w : r.warnings)
    warn(core::Code::GrblWarning, stripped_.cols.front(), std::move(w));
  if (r.failure) return fail(*r.failure);
  Restore& kept = next_.restore;
  if (r.restore_modes && !kept.modes && !kept.motion) kept.before = next_.modal;
  if (r.restore_modes) kept.modes = kept.motion = true;
  if (r.reset) {
    // Grbl's G0 goes on the next line moving with the modal motion: a G0
    // of its own is a move to where the tool is for the interpreter.
    next_.modal = Modal{};
    kept = Restore{};
    kept.motion = true;
  }
  facts_ = {Travel::of(*next_settings_), next_.modal.tool_length_mm, r.jog, r.homing};
  if (r.handed.empty()) {
    accept();
    return LineKind::Nothing;
  }
  handed_ = std::move(r.handed);
  handed_made_ = true;
  plain_ = false;
  block_col_ = 1;
  return LineKind::Run;
}

LineKind LineReader::fail(const Failure& f) {
  core::SourceLoc at = loc_;
  at.col = f.col;
  at.length = 1;
  diags_->push_back(
      {core::Code::GrblError, core::Severity::Error, at, error_message(f.number, f.detail)});
  return LineKind::Refused;
}

void LineReader::warn(core::Code code, std::uint32_t col, std::string message) {
  core::SourceLoc at = loc_;
  at.col = col;
  diags_->push_back({code, core::Severity::Warning, at, std::move(message)});
}

}  // namespace usina::gcode::grbl
