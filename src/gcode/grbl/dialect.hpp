// The grbl dialect (Grbl 1.1, docs/grbl.md): Grbl's line reader, its word
// and block checks with Grbl's error numbers, and its `$` system commands.
// The checked program is then run by the RS274NGC interpreter (grbl/dialect.cpp), so
// the geometry is the shared one; these files only say what Grbl accepts.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <tl/expected.hpp>

#include "core/diagnostic.hpp"
#include "core/vec3.hpp"
#include "gcode/code_table.hpp"
#include "gcode/dialect.hpp"
#include "gcode/interp/evaluated_block.hpp"

namespace usina::gcode::grbl {

// Grbl's own text for an error number (1–38, [err] of docs/grbl.md); empty
// for a number Grbl does not use.
std::string_view error_text(int number);

// The Grbl number an interpreter diagnostic stands for; 0 when Grbl has
// none (the diagnostic is then reported as usina's own).
int error_for(core::Code code);

// The message of a Grbl error: "grbl error:22 (Undefined feed rate): detail".
std::string error_message(int number, std::string_view detail);

// Why Grbl refuses a line: its error number, the 1-based column in the
// original line, and what usina adds to Grbl's text.
struct Failure {
  int number = 0;
  std::uint32_t col = 0;
  std::string detail;
};

// A check of Grbl's that passes, or the error:N it gives.
using Checked = tl::expected<void, Failure>;

// A line as Grbl's line reader leaves it ([proto]): upper case, no blanks or
// control characters, no comments, no '/', no real-time characters.
struct StrippedLine {
  std::string text;                 // what Grbl's parser sees
  std::vector<std::uint32_t> cols;  // 1-based column of each character of text
  std::uint32_t realtime_col = 0;   // first real-time character (? ~ ! ^X), 0 if none
  std::uint32_t control_col = 0;    // first control character outside comments (NUL...), 0 if none
  unsigned char control = 0;        // that character
};

StrippedLine strip_line(std::string_view line);
// The same into `out`, whose buffers are reused: nothing is allocated a line
// once they are as long as the longest line.
void strip_line(std::string_view line, StrippedLine& out);

// A line of a program: Grbl ends a line at LF or CR (protocol_main_loop),
// so CR LF, LF and CR alone each end one. The offset of its first byte, its
// length without the line end, and where the next line starts.
struct LineSpan {
  std::uint64_t offset = 0;
  std::size_t length = 0;
  std::uint64_t next = 0;
};

// The line starting at `offset` (< text.size()); lines are read one at a
// time, so no table of them is kept whatever the program's length.
LineSpan read_line(std::string_view text, std::uint64_t offset);

// Grbl's LINE_BUFFER_SIZE is 80 with the terminator.
inline constexpr std::size_t kMaxLineLength = 79;

struct Word {
  char letter = 0;
  double value = 0.0;
  std::uint32_t col = 0;
};

// Grbl's words: a letter and a number (sign, digits, one point). error:1 when
// a word does not start with a letter, error:2 when the number is bad.
Checked read_words(std::string_view text, const std::vector<std::uint32_t>& cols,
                   std::vector<Word>& out);

// Most lines of a program, read without stripping them first: upper-case
// words (a letter and a number) apart or with blanks between them. Their
// words at the user's columns, and `kept` the characters strip_line keeps
// of the line; false for any other line (blank, comments, lower case, a
// blank inside a word, an error...), which strip_line and read_words read.
bool read_plain_words(std::string_view line, std::vector<Word>& out, std::size_t& kept);

// A plain line of one plain move (StraightWords: X Y Z F, G0 or G1), read
// in one pass: the move, `kept` as read_plain_words gives it, and the
// column of its first word; false for any other line.
bool read_straight_line(std::string_view line, PlainMove& move, std::size_t& kept,
                        std::uint32_t& first_col);

// What the checks need to know between blocks (a subset of Grbl's gc_state).
struct Modal {
  int motion = 0;  // tenths: 0, 10, 20, 30, 382..385, 800; Grbl starts in G0
  int plane = 170;
  bool incremental = false;
  bool inch = false;
  bool inverse_time = false;
  double feed_mm = 0.0;         // 0: undefined (Grbl's F0)
  double tool_length_mm = 0.0;  // G43.1 Z, added to Z's machine position (G49: 0)

  bool operator==(const Modal&) const = default;
};

// What a checked block asks of the interpreter's copy of the line.
struct Accepted {
  bool program_end = false;  // M2 or M30
  bool uses_motion = false;  // axis words moved by the modal motion (no motion code of its own)
  bool sets_motion = false;  // a motion code in the block
  bool sets_distance = false;
  bool sets_feed_mode = false;
  bool sets_feed = false;

  bool operator==(const Accepted&) const = default;
};

// Grbl reads a code's whole part from 0 to 255 (G255.9 at most).
inline constexpr int kMaxCodeTenths = 2559;

// The grbl table indexed (gcode/code_table.hpp).
inline CodeIndex code_index(const Dialect& d) {
  return CodeIndex(d.name, d.codes, kMaxCodeTenths);
}

// Grbl's checks of one G-code block (gc_execute_line steps 1–3); on success
// `state` is what it is after the block.
Checked check_block(const CodeIndex& codes, const OptionValues& options,
                    const std::vector<Word>& words, Modal& state, Accepted& out);

// check_block's shortcut alone: a block of one plain move (X Y Z F and at
// most a G0 or G1, grbl/check.cpp) checked, with `state` and `out` as
// check_block leaves them, and the move for Interpreter::run_plain_move;
// false, and nothing changed, for any other block.
bool check_plain_block(const std::vector<Word>& words, Modal& state, Accepted& out,
                       PlainMove& move);

// Its two halves. The words of a plain move, added one at a time: false
// for a word that makes the block another (a letter but X Y Z F G, a
// letter twice, a G but G0 or G1, a negative F).
// The move is written where it is kept: a move built apart and copied
// there is read back 16 bytes at a time before its narrower fields' stores
// have landed (a stalled store forward a line, issue 19).
struct StraightWords {
  explicit StraightWords(PlainMove& into) : move(into) { move = {}; }

  PlainMove& move;
  std::uint32_t seen = 0;  // a bit a letter

  // Inline: it runs for every word of most lines.
  bool add(char letter, double value) {
    constexpr std::uint32_t kPlain = (1u << ('X' - 'A')) | (1u << ('Y' - 'A')) |
                                     (1u << ('Z' - 'A')) | (1u << ('G' - 'A')) |
                                     (1u << ('F' - 'A'));
    if (letter < 'A' || letter > 'Z') return false;
    const std::uint32_t bit = 1u << (letter - 'A');
    if ((kPlain & bit) == 0 || (seen & bit) != 0) return false;
    seen |= bit;
    if (letter == 'F' && !(value >= 0.0)) return false;
    return move.take(letter, value);
  }
};

// Grbl's checks of the move in its modal state (G94, G0 or G1 in force
// after it, a feed rate for a feed): `state` and `out` as check_block
// leaves them, or false and nothing changed.
bool check_plain_move(const PlainMove& move, Modal& state, Accepted& out);

// The same, every block the whole way: without the shortcut check_block
// takes for a plain move (for the test that compares the two).
Checked check_block_whole(const CodeIndex& codes, const OptionValues& options,
                          const std::vector<Word>& words, Modal& state, Accepted& out);

// Grbl's settings ($x=value) that usina reads; the others are recorded only.
struct Settings {
  std::map<int, double> values;
  double get(int n) const;
};

// Grbl's machine travel (system_check_travel_limits in [sys]): machine space
// is negative from the home at 0, each axis from -$13x to 0 (the default
// build: no HOMING_FORCE_SET_ORIGIN, so $23 does not move it).
struct Travel {
  bool soft_limits = false;      // $20
  core::Vec3 max;                // $130 $131 $132, mm
  double arc_tolerance = 0.002;  // $12: Grbl checks each segment's end

  static Travel of(const Settings& s);
  // The first axis of `machine` beyond the travel (0 1 2), or -1.
  int beyond(const core::Vec3& machine) const;
  bool operator==(const Travel&) const = default;
};

// What the soft-limit check needs to know of the line whose moves it checks
// (grbl/machine_check.cpp): the machine's travel, the G43.1 tool length,
// and whether the line is a jog or a homing.
struct MachineFacts {
  Travel travel;
  double tool_length_mm = 0.0;
  bool jog = false;     // $J=: a move beyond the travel is error:15, not alarm 2
  bool homing = false;  // $H: not checked (Grbl's homing is not)
};

// What a line hands the interpreter (evaluated_block.hpp): Grbl's own words
// as it read them, and the words usina adds for it (a jog's or a homing's
// move, the modes a jog kept; column 0: their diagnostics point at the line).
struct HandedBlock {
  std::vector<EvaluatedWord> words;
  std::vector<EvaluatedAssign> assigns;

  void clear() {
    words.clear();
    assigns.clear();
  }

  bool empty() const { return words.empty() && assigns.empty(); }

  void add(char letter, double value) { words.push_back({letter, value, 0}); }
};

// A `$` line. `handed` receives what the interpreter runs in its place (a
// jog's or a homing's move, a reset's modes), empty when nothing.
struct SystemResult {
  std::optional<Failure> failure;
  HandedBlock handed;
  bool restore_modes = false;  // the move changed modes Grbl keeps: put them back
  bool reset = false;          // a soft reset follows ($RST=): the modal state is Grbl's power-on
  bool homing = false;         // $H
  bool jog = false;            // $J= with a move
  std::vector<std::string> warnings;
};

SystemResult system_command(const CodeIndex& codes, const OptionValues& options,
                            std::string_view text, const std::vector<std::uint32_t>& cols,
                            const Modal& state, Settings& settings);

}  // namespace usina::gcode::grbl
