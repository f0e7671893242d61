// The plain-move shortcut of Grbl's block check (grbl/check.cpp) against
// the whole check: random blocks of plain words mixed with the words and
// values that take them off the shortcut (other codes, repeated letters,
// negative or zero feeds, N, S, T, fractions), from random modal states (G0
// to G80, G93, inch, no feed rate), give the same verdict, Grbl error
// number and column, modal state after and what the interpreter is asked.
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "gcode/grbl/dialect.hpp"
#include "gcode/grbl/runner.hpp"

namespace usina::gcode::grbl {
namespace {

Word random_word(std::mt19937& rng, std::uint32_t col) {
  struct Choice {
    char letter;
    double value;
  };

  static const Choice kWords[] = {
      {'G', 0},   {'G', 1},     {'G', 0},  {'G', 1},    {'G', 2},    {'G', 3},    {'G', 80},
      {'G', 93},  {'G', 94},    {'G', 20}, {'G', 91},   {'G', 38.2}, {'G', 1.5},  {'G', 17},
      {'X', 1.5}, {'X', -2.25}, {'Y', 0},  {'Y', 3},    {'Z', -1.5}, {'Z', 7},    {'X', 4},
      {'F', 600}, {'F', 0},     {'F', -5}, {'F', 1500}, {'N', 10},   {'S', 1000}, {'T', 2},
      {'M', 3},   {'I', 1},     {'R', 2},  {'P', 1},    {'A', 1},    {'Y', -8},   {'Z', 0.5}};
  const Choice& c = kWords[rng() % std::size(kWords)];
  return {c.letter, c.value, col};
}

Modal random_state(std::mt19937& rng) {
  static const int kMotions[] = {0, 10, 10, 0, 20, 30, 800, 382};
  Modal m;
  m.motion = kMotions[rng() % std::size(kMotions)];
  m.inch = rng() % 4 == 0;
  m.inverse_time = rng() % 5 == 0;
  m.incremental = rng() % 4 == 0;
  m.feed_mm = rng() % 3 == 0 ? 0.0 : 250.0;
  return m;
}

// The words the shortcut reads: G0, G1, X, Y, Z, F.
bool plain_words(const std::vector<Word>& words) {
  for (const Word& w : words) {
    const bool code = w.letter == 'G' && (w.value == 0 || w.value == 1);
    if (!code && w.letter != 'X' && w.letter != 'Y' && w.letter != 'Z' && w.letter != 'F')
      return false;
  }
  return true;
}

void expect_same(const Checked& a, const Checked& b) {
  ASSERT_EQ(a.has_value(), b.has_value());
  if (a) return;
  EXPECT_EQ(a.error().number, b.error().number);
  EXPECT_EQ(a.error().col, b.error().col);
  EXPECT_EQ(a.error().detail, b.error().detail);
}

TEST(GrblPlainBlock, EveryBlockGetsTheWholeChecksVerdictAndState) {
  const Dialect& d = grbl_dialect();
  const CodeIndex codes = code_index(d);
  const OptionValues options = default_options(d);
  std::mt19937 rng(19);
  int shortcut = 0;
  for (int i = 0; i < 20000; ++i) {
    std::vector<Word> words;
    const int n = static_cast<int>(rng() % 6);
    for (int k = 0; k < n; ++k)
      words.push_back(random_word(rng, static_cast<std::uint32_t>(1 + 6 * k)));
    const Modal start = random_state(rng);
    Modal fast = start, whole = start;
    Accepted fast_out, whole_out;
    const Checked a = check_block(codes, options, words, fast, fast_out);
    const Checked b = check_block_whole(codes, options, words, whole, whole_out);
    SCOPED_TRACE(::testing::Message() << "block " << i);
    expect_same(a, b);
    if (!a || !b) continue;
    EXPECT_TRUE(fast == whole) << "the modal state after the block differs";
    EXPECT_TRUE(fast_out == whole_out) << "what the interpreter is asked differs";
    if (HasFailure()) return;
    shortcut += plain_words(words) && !start.inverse_time ? 1 : 0;
  }
  // Many blocks accepted are the shortcut's, not only its refusals.
  EXPECT_GT(shortcut, 1000);
}

// Blocks the shortcut takes, one of each kind, with what the whole check
// says of them: it is not the whole check that passes them all.
TEST(GrblPlainBlock, APlainFeedWithoutARateIsTheWholeChecksError22) {
  const Dialect& d = grbl_dialect();
  const CodeIndex codes = code_index(d);
  const OptionValues options = default_options(d);
  Modal state;  // G0, no feed rate
  Accepted out;
  const std::vector<Word> g1{{'G', 1, 1}, {'X', 5, 4}};
  const Checked r = check_block(codes, options, g1, state, out);
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().number, 22);
  EXPECT_EQ(state.motion, 0);  // a refused block changes nothing
  const std::vector<Word> g1f{{'G', 1, 1}, {'X', 5, 4}, {'F', 100, 8}};
  ASSERT_TRUE(check_block(codes, options, g1f, state, out));
  EXPECT_EQ(state.motion, 10);
  EXPECT_EQ(state.feed_mm, 100.0);
  EXPECT_TRUE(out.sets_motion && out.sets_feed && !out.uses_motion);
  const std::vector<Word> y{{'Y', 2, 1}};
  ASSERT_TRUE(check_block(codes, options, y, state, out));
  EXPECT_TRUE(out.uses_motion && !out.sets_motion && !out.sets_feed);
}

}  // namespace
}  // namespace usina::gcode::grbl
