// --dialect auto's rules (docs/fanuc.md §12), one program text each.
#include <gtest/gtest.h>

#include "gcode/dialect_guess.hpp"

namespace usina::gcode {
namespace {

TEST(FanucGuess, EachRuleFires) {
  EXPECT_EQ(guess_dialect("$H\nG0 X1\n").dialect, "grbl");
  EXPECT_EQ(guess_dialect("o<side> sub\nG0 X1\no<side> endsub\nM2\n").dialect, "rs274ngc");
  EXPECT_EQ(guess_dialect("o100 while [#1 LT 3]\no100 endwhile\nM2\n").dialect, "rs274ngc");
  EXPECT_EQ(guess_dialect("%\nO1234 (PART)\nG0 X1.\nM30\n%\n").dialect, "fanuc");
  EXPECT_EQ(guess_dialect("G0 X1.\nWHILE [#1 LT 3] DO1\nEND1\n").dialect, "fanuc");
  EXPECT_EQ(guess_dialect("G65 P9100 A1.\nM30\n").dialect, "fanuc");
  EXPECT_EQ(guess_dialect("N10 G0 X10 #N20 G1 X5 #\n").dialect, "romi");
  EXPECT_EQ(guess_dialect("G0 X#1\n#1 = 5\nM2\n").dialect, "rs274ngc");
  EXPECT_EQ(guess_dialect("").dialect, "rs274ngc");
}

TEST(FanucGuess, CommentsDoNotCount) {
  EXPECT_EQ(guess_dialect("(WHILE [#1 LT 3] DO1)\nG0 X1\nM2\n").dialect, "rs274ngc");
  EXPECT_FALSE(guess_dialect("%\nO0001\nM30\n%\n").reason.empty());
}

}  // namespace
}  // namespace usina::gcode
