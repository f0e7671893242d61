// Grbl's checks of a G-code block, in the order of gc_execute_line ([gc] of
// docs/grbl.md): the words (step 1), then the block's commands (step 3). The
// checks that need the position (arc geometry, probe targets) are the
// interpreter's and the runner's (grbl/dialect.cpp).
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>

#include <fmt/format.h>

#include "gcode/grbl/dialect.hpp"

namespace usina::gcode::grbl {
namespace {

enum class AxisCommand { None, NonModal, Motion, ToolLength };

constexpr std::uint32_t letter_bit(char letter) {
  return std::uint32_t{1} << (letter - 'A');
}

constexpr std::uint32_t letters_of(std::string_view set) {
  std::uint32_t bits = 0;
  for (const char c : set)
    bits |= letter_bit(c);
  return bits;
}

// A block's commands and values. Fixed arrays, not maps: a block is checked
// for every line of the program, and nothing is allocated for it.
struct BlockCodes {
  // Grbl's G groups are 0-13, its M groups 104-108 (grbl/dialect.cpp's table).
  static constexpr std::size_t slot(int group) {
    return static_cast<std::size_t>(group < 100 ? group : group - 100 + 16);
  }

  std::array<int, 32> by_group;  // group → code (tenths), -1: none
  AxisCommand axis = AxisCommand::None;
  std::uint32_t letters = 0;  // a bit a letter of the value words read

  BlockCodes() { by_group.fill(-1); }

  bool has(int group) const { return by_group[slot(group)] >= 0; }

  int code(int group) const { return by_group[slot(group)]; }

  void set_code(int group, int code) { by_group[slot(group)] = code; }

  bool has_value(char l) const { return (letters & letter_bit(l)) != 0; }

  // A value word read (has_value(l)).
  Word value(char l) const {
    const auto i = static_cast<std::size_t>(l - 'A');
    return {l, values[i], cols[i]};
  }

  void set_value(const Word& w) {
    const auto i = static_cast<std::size_t>(w.letter - 'A');
    values[i] = w.value;
    cols[i] = w.col;
    letters |= letter_bit(w.letter);
  }

 private:
  // Read only where `letters` has the bit: not cleared for every block.
  std::array<double, 26> values;
  std::array<std::uint32_t, 26> cols;
};

constexpr int kNonModal = 0, kMotion = 1, kPlane = 2, kDistance = 3, kFeedMode = 5, kUnits = 6,
              kToolLength = 8, kStop = 104;

// Integer G codes whose fractions Grbl reads itself: an unknown fraction is
// error:20 there, error:23 on any other code.
bool fraction_family(int g) {
  return g == 28 || g == 30 || g == 38 || g == 43 || g == 61 || g == 90 || g == 91 || g == 92;
}

std::string code_name(char letter, double value) {
  return fmt::format("{}{}", letter, value);
}

Checked read_code(const CodeIndex& codes, const OptionValues& options, const Word& w,
                  BlockCodes& b) {
  const double integer = std::trunc(w.value);
  if (integer < 0 || integer > 255) {
    return tl::unexpected(
        Failure{20, w.col, code_name(w.letter, w.value) + " is not a Grbl command"});
  }
  const int iv = static_cast<int>(integer);
  // A whole code (most of them) asks no rounding of its fraction: lround
  // is a call into libm for every G and M word (issue 19).
  const int mantissa =
      w.value == integer ? 0 : static_cast<int>(std::lround(100.0 * (w.value - integer)));
  if (w.letter == 'M' && mantissa > 0) {
    return tl::unexpected(
        Failure{23, w.col, code_name('M', w.value) + ": M codes take no fraction"});
  }
  const CodeEntry* e = mantissa % 10 == 0 ? codes.find(w.letter, iv * 10 + mantissa / 10) : nullptr;
  // A code of the table has its whole part in it: the search for the
  // whole part alone is made only for a code the table lacks.
  if ((e == nullptr && !codes.has_integer(w.letter, iv)) ||
      (w.letter == 'M' && iv == 7 && options.count("grbl_m7") && options.at("grbl_m7") == "off")) {
    return tl::unexpected(
        Failure{20, w.col, code_name(w.letter, w.value) + " is not a Grbl 1.1 command"});
  }
  if (w.letter == 'G') {
    AxisCommand kind = AxisCommand::None;
    if (iv <= 3 || iv == 38) kind = AxisCommand::Motion;
    if ((iv == 10 || iv == 28 || iv == 30 || iv == 92) && mantissa == 0)
      kind = AxisCommand::NonModal;
    if (iv == 43 || iv == 49) kind = AxisCommand::ToolLength;
    if (kind != AxisCommand::None) {
      if (b.axis != AxisCommand::None) {
        return tl::unexpected(Failure{
            24, w.col, code_name('G', w.value) + " and another command both use the axis words"});
      }
      b.axis = kind;
    }
  }
  if (e == nullptr) {
    if (w.letter == 'G' && fraction_family(iv)) {
      return tl::unexpected(
          Failure{20, w.col, code_name('G', w.value) + " is not a Grbl 1.1 command"});
    }
    return tl::unexpected(
        Failure{23, w.col, code_name(w.letter, w.value) + " must be a whole number"});
  }
  const int group = e->group;
  if (BlockCodes::slot(group) >= b.by_group.size()) {
    return tl::unexpected(
        Failure{20, w.col, code_name(w.letter, w.value) + " is not a Grbl 1.1 command"});
  }
  if (b.has(group)) {
    return tl::unexpected(Failure{21, w.col,
                                  code_name(w.letter, w.value) +
                                      " is in the modal group of another "
                                      "command of the block"});
  }
  b.set_code(group, e->code);
  return {};
}

Checked read_value(const Word& w, BlockCodes& b) {
  // Sets of letters as bits: a search of a string called memchr for every
  // word of every block (issue 19).
  constexpr std::uint32_t kLetters = letters_of("FIJKLNPRSTXYZ");
  constexpr std::uint32_t kNotNegative = letters_of("FNPTS");
  if ((kLetters & letter_bit(w.letter)) == 0) {
    return tl::unexpected(
        Failure{20, w.col,
                fmt::format("{} words are not in Grbl (3 axes X Y Z; no A B C D E H Q U V W, "
                            "no O-words)",
                            w.letter)});
  }
  if (w.letter == 'T' && w.value > 255) {
    return tl::unexpected(
        Failure{38, w.col, fmt::format("T{} is above Grbl's largest tool number 255", w.value)});
  }
  if (b.has_value(w.letter)) {
    return tl::unexpected(
        Failure{25, w.col, fmt::format("{} word appears twice in the block", w.letter)});
  }
  if ((kNotNegative & letter_bit(w.letter)) != 0 && w.value < 0) {
    return tl::unexpected(
        Failure{4, w.col, fmt::format("{}{} must not be negative", w.letter, w.value)});
  }
  b.set_value(w);
  return {};
}

struct Step3 {
  const BlockCodes& b;
  Modal next;
  std::uint32_t unused;  // letters of the value words no command has used yet
  std::uint32_t col0;    // column of the block's first word

  bool has(char l) const { return b.has_value(l); }

  double get(char l) const { return b.value(l).value; }

  std::uint32_t col(char l) const { return has(l) ? b.value(l).col : col0; }

  std::uint32_t code_col() const { return col0; }

  bool axis_words() const { return has('X') || has('Y') || has('Z'); }

  void use(char l) { unused &= ~letter_bit(l); }
};

// In-plane axis and offset letters.
std::pair<char, char> plane_axes(int plane) {
  if (plane == 180) return {'Z', 'X'};
  if (plane == 190) return {'Y', 'Z'};
  return {'X', 'Y'};
}

std::pair<char, char> plane_offsets(int plane) {
  if (plane == 180) return {'K', 'I'};
  if (plane == 190) return {'J', 'K'};
  return {'I', 'J'};
}

Checked feed_rate(Step3& s) {
  const bool inverse = s.b.has(kFeedMode) ? s.b.code(kFeedMode) == 930 : s.next.inverse_time;
  const int motion = s.b.has(kMotion) ? s.b.code(kMotion) : s.next.motion;
  if (inverse) {
    if (s.b.axis == AxisCommand::Motion && motion != 0 && motion != 800 && !s.has('F')) {
      return tl::unexpected(
          Failure{22, s.code_col(), "G93 inverse time: every feed move needs its own F"});
    }
    s.next.feed_mm = s.has('F') ? s.get('F') : 0.0;
  } else if (s.has('F')) {
    s.next.feed_mm = s.get('F') * (s.next.inch ? 25.4 : 1.0);
  } else if (s.next.inverse_time) {
    s.next.feed_mm = 0.0;  // leaving G93: the feed rate is undefined again
  }
  s.next.inverse_time = inverse;
  s.use('F');
  return {};
}

Checked non_modal(Step3& s) {
  if (!s.b.has(kNonModal)) return {};
  const int g = s.b.code(kNonModal);
  if (g == 40) {
    if (!s.has('P')) return tl::unexpected(Failure{28, s.code_col(), "G4 needs P (seconds)"});
    s.use('P');
  } else if (g == 100) {
    if (!s.axis_words()) return tl::unexpected(Failure{26, s.code_col(), "G10 needs axis words"});
    if (!s.has('P') && !s.has('L'))
      return tl::unexpected(Failure{28, s.code_col(), "G10 needs L and P"});
    const double p = s.has('P') ? std::trunc(s.get('P')) : 0.0;
    if (p > 6)
      return tl::unexpected(
          Failure{29, s.col('P'), fmt::format("G10 P{}: Grbl has G54-G59 (P0-P6)", p)});
    const double l = s.has('L') ? s.get('L') : 0.0;
    if (l != 20 && (l != 2 || s.has('R'))) {
      return tl::unexpected(Failure{
          20, s.col('L'),
          s.has('R') && l == 2 ? "G10 L2 takes no R (no rotation)" : "G10 takes L2 or L20"});
    }
    s.use('P');
    s.use('L');
  } else if (g == 530) {
    const int motion = s.b.has(kMotion) ? s.b.code(kMotion) : s.next.motion;
    if (motion != 0 && motion != 10) {
      return tl::unexpected(Failure{30, s.code_col(), "G53 needs G0 or G1 as the motion mode"});
    }
  } else if (g == 920) {
    if (!s.axis_words()) return tl::unexpected(Failure{26, s.code_col(), "G92 needs axis words"});
  }
  return {};
}

Checked arc(Step3& s) {
  if (!s.axis_words()) {
    return tl::unexpected(
        Failure{26, s.code_col(), "G2/G3 needs axis words (Grbl has no full circle without them)"});
  }
  const auto [a0, a1] = plane_axes(s.next.plane);
  if (!s.has(a0) && !s.has(a1)) {
    return tl::unexpected(Failure{
        32, s.code_col(), fmt::format("G2/G3 needs {} or {}, an axis word in the plane", a0, a1)});
  }
  if (s.has('R')) {
    s.use('R');
    return {};
  }
  const auto [o0, o1] = plane_offsets(s.next.plane);
  if (!s.has(o0) && !s.has(o1)) {
    return tl::unexpected(Failure{
        35, s.code_col(), fmt::format("G2/G3 needs R, or {} or {} for the centre", o0, o1)});
  }
  s.use('I');
  s.use('J');
  s.use('K');
  return {};
}

Checked motion(Step3& s) {
  if (s.next.motion == 800) {
    if (s.axis_words())
      return tl::unexpected(Failure{31, s.col('X'), "axis words with G80 (no motion mode)"});
    return {};
  }
  if (s.b.axis != AxisCommand::Motion) return {};
  const int m = s.next.motion;
  if (m == 0) return {};
  if (s.next.feed_mm == 0.0) {
    return tl::unexpected(Failure{22, s.code_col(), "a feed move with no feed rate set (F)"});
  }
  if (m == 20 || m == 30) return arc(s);
  if (m >= 382 && m <= 385 && !s.axis_words()) {
    return tl::unexpected(Failure{26, s.code_col(), "G38.x needs axis words (the probe target)"});
  }
  return {};
}

Checked step3(const BlockCodes& b, std::uint32_t col0, Modal& state) {
  Step3 s{b, state, b.letters, col0};
  if (s.has('N') && s.get('N') > 10'000'000) {
    return tl::unexpected(Failure{27, s.col('N'), "line number above 10,000,000"});
  }
  // The block's modes first: the checks below see them (Grbl's gc_block.modal).
  if (b.has(kUnits)) s.next.inch = b.code(kUnits) == 200;
  if (b.has(kPlane)) s.next.plane = b.code(kPlane);
  if (b.has(kDistance)) s.next.incremental = b.code(kDistance) == 910;
  if (auto f = feed_rate(s); !f) return f;
  if (b.has(kToolLength) && b.code(kToolLength) == 431 &&
      (!s.has('Z') || s.has('X') || s.has('Y'))) {
    return tl::unexpected(Failure{37, s.code_col(), "G43.1 takes a Z word only"});
  }
  if (b.has(kToolLength)) {
    s.next.tool_length_mm =
        b.code(kToolLength) == 431 ? s.get('Z') * (s.next.inch ? 25.4 : 1.0) : 0.0;
  }
  if (b.has(kMotion)) s.next.motion = b.code(kMotion);
  if (auto f = non_modal(s); !f) return f;
  if (auto f = motion(s); !f) return f;
  s.unused &= ~letters_of("NFSTXYZ");
  if (s.unused != 0) {
    // The first in the alphabet, as Grbl's check of its value words.
    const Word w = b.value(static_cast<char>('A' + std::countr_zero(s.unused)));
    return tl::unexpected(Failure{
        36, w.col, fmt::format("{} word is not used by any command of the block", w.letter)});
  }
  state = s.next;
  return {};
}

}  // namespace

// The shortcut of a plain move: a block of X Y Z F words and at most one
// G0 or G1, each letter once, F not negative, in G94, whose motion is G0
// or G1 after it and, for a feed, has a feed rate. Such a block is most
// lines of a long program, and every rule of the whole check lets it by
// with only its motion and feed rate kept: they are kept here, and the
// whole check is not run (a third of grbl's own work a line, issue 19).
// False, and nothing changed, for any other block; a block the whole
// check would refuse is one (the error is the whole check's to say). A
// test compares the two roads (tests/gcode/grbl/plain_block_test.cpp).
bool check_plain_move(const PlainMove& move, Modal& state, Accepted& out) {
  if (state.inverse_time) return false;
  const int m = move.motion >= 0 ? move.motion : state.motion;
  if (m != 0 && m != 10) return false;
  const bool sets_feed = (move.given & PlainMove::kF) != 0;
  const bool moves = move.motion >= 0 || (move.given & 7u) != 0;
  const double feed_mm = sets_feed ? move.f * (state.inch ? 25.4 : 1.0) : state.feed_mm;
  if (moves && m == 10 && feed_mm == 0.0) return false;
  state.feed_mm = feed_mm;
  state.motion = m;
  out = {};
  out.sets_motion = move.motion >= 0;
  out.uses_motion = moves && move.motion < 0;
  out.sets_feed = sets_feed;
  return true;
}

bool check_plain_block(const std::vector<Word>& words, Modal& state, Accepted& out,
                       PlainMove& move) {
  StraightWords straight(move);
  for (const Word& w : words)
    if (!straight.add(w.letter, w.value)) return false;
  return check_plain_move(move, state, out);
}

Checked check_block(const CodeIndex& codes, const OptionValues& options,
                    const std::vector<Word>& words, Modal& state, Accepted& out) {
  PlainMove move;
  if (check_plain_block(words, state, out, move)) return {};
  return check_block_whole(codes, options, words, state, out);
}

Checked check_block_whole(const CodeIndex& codes, const OptionValues& options,
                          const std::vector<Word>& words, Modal& state, Accepted& out) {
  out = {};
  BlockCodes b;
  for (const Word& w : words) {
    auto f =
        (w.letter == 'G' || w.letter == 'M') ? read_code(codes, options, w, b) : read_value(w, b);
    if (!f) return f;
  }
  if (b.axis == AxisCommand::None && (b.has_value('X') || b.has_value('Y') || b.has_value('Z')))
    b.axis = AxisCommand::Motion;  // axis words alone move with the modal motion
  const std::uint32_t col0 = words.empty() ? 1 : words.front().col;
  if (auto f = step3(b, col0, state); !f) return f;
  out.sets_motion = b.has(kMotion);
  out.uses_motion = b.axis == AxisCommand::Motion && !out.sets_motion;
  out.sets_distance = b.has(kDistance);
  out.sets_feed_mode = b.has(kFeedMode);
  out.sets_feed = b.has_value('F');
  out.program_end = b.has(kStop) && (b.code(kStop) == 20 || b.code(kStop) == 300);
  return {};
}

}  // namespace usina::gcode::grbl
