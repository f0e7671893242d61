// The plain-move shortcut (romi/plain_move.cpp) against the whole road:
// random programs that put plain moves beside every mode and form that
// changes how romi reads a move (G91, inch, lower-case increments, mirror,
// scale, rotation, polar and tangent forms, R blends, G81 and its patterns,
// compensation, parameters, comments, repeated letters, no feed) give the
// same operations and the same diagnostics both ways.
#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "romi_test_support.hpp"

namespace usina::gcode::romi_test {
namespace {

std::string coordinate(std::mt19937& rng) {
  std::uniform_real_distribution<double> v(-50.0, 50.0);
  const double x = v(rng);
  if (rng() % 8 == 0) return std::to_string(static_cast<int>(x));
  return fmt::format("{:.3f}", x);
}

std::string plain_move(std::mt19937& rng) {
  static const char* const kMotions[] = {"G0", "G1", "G00", "G01", "", "", "G01"};
  std::vector<std::string> words;
  if (const std::string g = kMotions[rng() % 7]; !g.empty()) words.push_back(g);
  for (const char axis : {'X', 'Y', 'Z'}) {
    if (rng() % 10 >= 6) continue;
    // Now and then lower case (an increment), twice, or a parameter.
    const auto odd = rng() % 1000;
    const char letter = odd == 0 ? static_cast<char>(axis - 'A' + 'a') : axis;
    words.push_back(letter + (odd == 1 ? std::string("P1") : coordinate(rng)));
    if (odd == 2) words.push_back(axis + coordinate(rng));
  }
  if (rng() % 5 == 0) words.push_back(fmt::format("F{}", rng() % 100 == 0 ? 0 : 1 + rng() % 3000));
  std::shuffle(words.begin(), words.end(), rng);
  std::string block;
  for (const std::string& w : words)
    block += (block.empty() ? "" : " ") + w;
  return block;
}

std::string program(unsigned seed) {
  static const char* const kOthers[] = {"G91",
                                        "G90",
                                        "G70",
                                        "G71",
                                        "G31 X0",
                                        "G31 Y5",
                                        "G30",
                                        "G72 K2",
                                        "G72 K1",
                                        "G73 C30",
                                        "G73 C0",
                                        "G01 R5 A30",
                                        "G01 C45",
                                        "T2 M06;d6",
                                        "G81 R2 Z-5 F150",
                                        "G80",
                                        "G41",
                                        "G40",
                                        "M03",
                                        "M05",
                                        "(P1 = 7)",
                                        ";a comment",
                                        "G0 X1 ;moving on",
                                        "G17",
                                        "N100 G0 X2"};
  // Forms that stop a program where they stand (a blend before a block that
  // does not move, a pattern without its cycle...): now and then.
  static const char* const kRare[] = {"G02 R10",    "G25 X10 Y10 I2 J2", "G03 X10 Y10 I5 J5",
                                      "G03 R5 C90", "G01 X5 F-5",        "G00 X5 F-5"};
  std::mt19937 rng(seed);
  std::string text = "G71 G90 G17#T1 M06;d8#F500#G0 X1 Y1#";
  const auto blocks = 20 + rng() % 60;
  for (std::size_t i = 0; i < blocks; ++i) {
    const auto pick = rng() % 100;
    text += pick < 1    ? std::string(kRare[rng() % std::size(kRare)])
            : pick < 27 ? std::string(kOthers[rng() % std::size(kOthers)])
                        : plain_move(rng);
    text += rng() % 3 == 0 ? "#\n" : "#";
  }
  return text + "M02#\n";
}

TEST(RomiPlainMove, TheShortcutWritesWhatTheWholeRoadWrites) {
  const int finished = dialect_test::expect_shortcut_agrees("romi", program, 300);
  // Enough of them run to their end to reach every mode.
  EXPECT_GT(finished, 100);
}

}  // namespace
}  // namespace usina::gcode::romi_test
