// The interpreter's plain-move shortcut (interp/plain_move.cpp) against the
// whole road: random programs that put plain moves (G0/G1 X Y Z F) beside
// every mode and word that changes how the interpreter runs a move (inch,
// G91, G93/G95, cutter compensation on and holding, G7 diameters, tool
// changes, cycles, arcs, polar words, G53, comments, assignments, repeated
// letters, no feed rate, values the canon refuses, unknown codes) give the
// same operations, diagnostics and final modes both ways: in rs274ngc,
// whose run stops at an error, and in grbl, which reports a refused block
// and reads on (the shortcut's own putting back). fanuc and romi run theirs
// through the same comparison (their plain_move_test.cpp).
#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "support/dialect_run.hpp"

namespace usina::gcode {
namespace {

std::string coordinate(std::mt19937& rng) {
  std::uniform_real_distribution<double> v(-50.0, 50.0);
  switch (rng() % 400) {
  case 0: return "999999999";   // in a word's range; beyond the canon's under G20
  case 1: return "1000000001";  // beyond a word's range
  case 2: return std::to_string(static_cast<int>(v(rng)));
  default: return fmt::format("{:.4f}", v(rng));
  }
}

std::string plain_move(std::mt19937& rng) {
  static const char* const kMotions[] = {"G0", "G1", "G00", "G01", "", "", "G1"};
  std::vector<std::string> words;
  if (const std::string g = kMotions[rng() % 7]; !g.empty()) words.push_back(g);
  for (const char axis : {'X', 'Y', 'Z'}) {
    if (rng() % 10 >= 6) continue;
    words.push_back(axis + coordinate(rng));
    if (rng() % 300 == 0) words.push_back(axis + coordinate(rng));  // twice
  }
  if (rng() % 5 == 0) {
    const auto odd = rng() % 60;
    words.push_back(odd == 0 ? "F0" : (odd == 1 ? "F-5" : fmt::format("F{}", 1 + rng() % 3000)));
  }
  if (rng() % 80 == 0) words.push_back("S1000");
  std::shuffle(words.begin(), words.end(), rng);
  std::string block;
  for (const std::string& w : words)
    block += (block.empty() ? "" : " ") + w;
  return block;
}

template <std::size_t N>
std::string program(unsigned seed, const char* start, const char* const (&others)[N],
                    unsigned other_in) {
  std::mt19937 rng(seed);
  std::string text = start;
  const auto blocks = 20 + rng() % 60;
  for (std::size_t i = 0; i < blocks; ++i)
    text += (rng() % other_in == 0 ? std::string(others[rng() % N]) : plain_move(rng)) + "\n";
  return text + "M2\n";
}

std::string rs274ngc_program(unsigned seed) {
  static const char* const kOthers[] = {"G20",
                                        "G21",
                                        "G91",
                                        "G90",
                                        "G93 G1 X1 F2\nG1 Y1 F3\nG94",
                                        "G95",
                                        "G41 D0",
                                        "G42",
                                        "G40",
                                        "G41.1 D2",
                                        "G40 G0 X0",
                                        "G7",
                                        "G8",
                                        "T1 M6",
                                        "T2 M6 G43 H2",
                                        "G49",
                                        "G81 X1 Y1 Z-2 R1",
                                        "G80",
                                        "G2 X5 Y0 R10",
                                        "G3 X0 Y0 I-2.5 J0",
                                        "G1 @5 ^30",
                                        "G53 G0 Z0",
                                        "G92 X0 Y0",
                                        "G92.1",
                                        "G10 L2 P1 X3",
                                        "G10 L2 P1 R30",
                                        "G55",
                                        "G54",
                                        "G18",
                                        "G17",
                                        "G1 X1 (comment)",
                                        "#1 = 5 G1 X#1",
                                        "G0 X[#1 * 2]",
                                        "G1.5 X1",
                                        "G4 P0.1",
                                        "M3 S1000",
                                        "F0",
                                        "G64 P0.1",
                                        "G61"};
  return program(seed, "G21 G90 G17 G94 G0 X0 Y0 Z5\nF500\n", kOthers, 4);
}

std::string grbl_program(unsigned seed) {
  static const char* const kOthers[] = {"G20",
                                        "G21",
                                        "G91",
                                        "G90",
                                        "G93 G1 X1 F2\nG1 Y1 F3\nG94",
                                        "G2 X5 Y0 R10",
                                        "G3 X0 Y0 I-2.5 J0",
                                        "G53 G0 Z0",
                                        "G92 X0 Y0",
                                        "G92.1",
                                        "G10 L2 P1 X3",
                                        "G55",
                                        "G54",
                                        "G18",
                                        "G17",
                                        "G1 X1 (comment)",
                                        "G4 P0.1",
                                        "M3 S1000",
                                        "G38.2 Z-1 F100",
                                        "G80",
                                        "G1.5 X1",
                                        "G43.1 Z1",
                                        "G49"};
  return program(seed, "G21 G90 G17 G94 G0 X0 Y0 Z5\nF500\n", kOthers, 4);
}

TEST(InterpPlainMove, Rs274ngcAgreesWithTheWholeRoad) {
  const int finished = dialect_test::expect_shortcut_agrees("rs274ngc", rs274ngc_program, 600);
  // Enough of them reach their end to have tried every mode (a run stops
  // at its first error).
  EXPECT_GT(finished, 30);
}

TEST(InterpPlainMove, GrblAgreesWithTheWholeRoadAndReadsOnAfterARefusal) {
  const int finished = dialect_test::expect_shortcut_agrees("grbl", grbl_program, 600);
  EXPECT_GT(finished, 30);
}

}  // namespace
}  // namespace usina::gcode
