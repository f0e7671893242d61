// The plain-move shortcut (fanuc/plain_move.cpp) against the whole road:
// random programs that put plain moves under every mode the front end
// changes moves in (scaling, rotation, mirror, polar coordinates and
// interpolation, canned cycles, modal macro calls, G69, incremental, inch,
// integer words, vacant variables, letters twice, values out of range)
// give the same operations and the same
// diagnostics both ways.
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "fanuc_test_support.hpp"

namespace usina::gcode::fanuc_test {
namespace {

std::string coordinate(std::mt19937& rng) {
  std::uniform_real_distribution<double> v(-50.0, 50.0);
  const double x = v(rng);
  if (rng() % 10 == 0) return std::to_string(static_cast<int>(x));  // no point
  if (rng() % 30 == 0) return fmt::format("+{:.3f}", std::fabs(x));
  return fmt::format("{:.3f}", x);
}

std::string plain_move(std::mt19937& rng) {
  static const char* const kMotions[] = {"G0", "G1", "G00", "G01", "", ""};
  std::vector<std::string> words;
  if (const std::string g = kMotions[rng() % 6]; !g.empty()) words.push_back(g);
  for (const char axis : {'X', 'Y', 'Z'})
    if (rng() % 10 < 6) words.push_back(axis + coordinate(rng));
  if (rng() % 5 == 0) words.push_back(fmt::format("F{}.", 1 + rng() % 3000));
  if (rng() % 20 == 0) words.push_back(fmt::format("S{}", 100 + rng() % 9000));
  // Rare, as each ends the run: a letter twice, a negative feed rate, a
  // value beyond usina's range (each an error of the whole road's).
  if (rng() % 400 == 0) words.push_back(words.empty() ? "Z1." : words.front());
  if (rng() % 400 == 0) words.push_back("F-100.");
  if (rng() % 400 == 0) words.push_back("Y2000000000.");
  std::shuffle(words.begin(), words.end(), rng);
  std::string block;
  for (const std::string& w : words)
    block += (block.empty() ? "" : " ") + w;
  return block;
}

std::string program(unsigned seed) {
  static const char* const kModes[] = {"G51 X0 Y0 P2000",
                                       "G50",
                                       "G68 X0 Y0 R30.",
                                       "G69",
                                       "G16",
                                       "G15",
                                       "G51.1 X0",
                                       "G50.1 X0",
                                       "G81 X1. Y1. Z-2. R1. F100.",
                                       "G83 X2. Y2. Z-3. R1. Q1. F100.",
                                       "G80",
                                       "G91",
                                       "G90",
                                       "G66 P9000 Z-1.",
                                       "G67",
                                       "G20",
                                       "G21",
                                       "G17",
                                       "G18",
                                       "G19",
                                       "G41 D11",
                                       "G40",
                                       "M3",
                                       "M5",
                                       "#1 = 5",
                                       "G0 X#1",
                                       "G1 X#2 Y1.",
                                       "G12.1",
                                       "G13.1",
                                       "G43 H1 Z10.",
                                       "G49",
                                       "G04 P100",
                                       "G10 L2 P1 X1.",
                                       "G54",
                                       "G55",
                                       "M98 P9001",
                                       "G31 X5. F100.",
                                       "G76 X1. Y1. Z-2. R1. Q0.5 F100."};
  std::mt19937 rng(seed);
  std::string text = "%\nO1000\nG21 G90 G17 G0 X0 Y0 Z5.\nF500.\n";
  const auto blocks = 20 + rng() % 60;
  for (std::size_t i = 0; i < blocks; ++i)
    text +=
        (rng() % 4 == 0 ? std::string(kModes[rng() % std::size(kModes)]) : plain_move(rng)) + "\n";
  return text + "M30\nO9000\nG1 X#24 Z#26 F100.\nM99\nO9001\nG0 X1. Y1.\nG1 X2.\nM99\n%\n";
}

std::string outcome(const std::string& text, bool whole_road) {
  return dialect_test::run_outcome("fanuc", text, whole_road);
}

TEST(FanucPlainMove, TheShortcutWritesWhatTheWholeRoadWrites) {
  const int finished = dialect_test::expect_shortcut_agrees("fanuc", program, 300);
  // Enough of them run to their end to reach every mode.
  EXPECT_GT(finished, 100);
}

// Sequences too rare for the random programs.
TEST(FanucPlainMove, TheShortcutKeepsOutOfRareModes) {
  const char* const programs[] = {
      // The first move after G69, incremental: a warning at it.
      "G68 X0 Y0 R30.\nG0 X1. Y1.\nG69\nG91\nX1. Y1.\nG90\nM30\n",
      // A plain move while a modal macro call is in force calls it.
      "G66 P9000 Z-1.\nG0 X1.\nX2.\nG67\nX3.\nM30\nO9000\nG1 Z#26 F100.\nM99\n",
      // G76's mode is the front end's own (the interpreter never enters it).
      "G0 Z10.\nG76 X1. Y1. Z-2. R1. Q0.5 F100.\nX5. Y5.\nG80\nX0 Y0\nM30\n"};
  for (const char* text : programs)
    EXPECT_EQ(outcome(text, false), outcome(text, true)) << text;
}

}  // namespace
}  // namespace usina::gcode::fanuc_test
