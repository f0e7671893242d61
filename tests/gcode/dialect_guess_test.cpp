// --dialect auto (docs/dialects.md, "Guessing the dialect"): each decisive
// mark and each weighed clue on a small made-up program.
#include "gcode/dialect_guess.hpp"

#include <string>

#include <gtest/gtest.h>

#include "gcode/dialect_clues.hpp"

namespace usina::gcode {
namespace {

bool says(const DialectGuess& g, const std::string& part) {
  return g.reason.find(part) != std::string::npos;
}

TEST(DialectGuess, PercentThenAProgramNameIsFanuc) {
  // Fanuc shop programs name themselves after the tape start: 'OWASHER'.
  const auto g = guess_dialect("%\nOWASHER(WASHER)\n#140=.625\nM98P#144\nM30\n%\n", "W.NC");
  EXPECT_EQ(g.dialect, "fanuc");
  EXPECT_TRUE(says(g, "OWASHER")) << g.reason;
  EXPECT_EQ(guess_dialect("%\n:0097\nG0 X1.\nM30\n%\n").dialect, "fanuc");
}

TEST(DialectGuess, APercentLineElsewhereIsNoProgramNumber) {
  // LinuxCNC wraps programs in '%' too; an O word further down is not Fanuc's.
  EXPECT_EQ(guess_dialect("%\nG0 X1\nO1\nM2\n%\n", "a.ngc").dialect, "rs274ngc");
}

TEST(DialectGuess, HaasIfThenIsMacroB) {
  EXPECT_EQ(guess_dialect("G0 X1\nIF [ #5405 GE 6000 ] THEN #3000= 15\nM30\n").dialect, "fanuc");
}

TEST(DialectGuess, NamedParameterIsLinuxCnc) {
  const auto g = guess_dialect("#<depth> = 2\nG1 Z-#<depth> F100\n", "job.gcode");
  EXPECT_EQ(g.dialect, "rs274ngc");
  EXPECT_TRUE(says(g, "named parameter")) << g.reason;
}

TEST(DialectGuess, ACommentNamingTheControlDecidesOverHabits) {
  // Named control (+6) against no end (+3) and '.gcode' (+1).
  const auto lcnc = guess_dialect("(post for LinuxCNC)\nG0 X1\n", "a.gcode");
  EXPECT_EQ(lcnc.dialect, "rs274ngc");
  EXPECT_TRUE(says(lcnc, "'linuxcnc'")) << lcnc.reason;
  EXPECT_EQ(guess_dialect("( Image2Gcode for Grbl )\nG0 X1\nM30\n", "a.nc").dialect, "grbl");
  EXPECT_EQ(guess_dialect("O100 ( HAAS )\nG0 X1\nM30\n", "a.nc").dialect, "fanuc");
  EXPECT_EQ(guess_dialect("(for a Shapeoko 3)\nG0 X1\nM30\n", "a.nc").dialect, "grbl");
}

TEST(DialectGuess, AControlNameInsideAnotherWordIsNone) {
  // 'haasX' and 'mach3d' are not the names of the controls.
  EXPECT_EQ(guess_dialect("(haasX mach3d)\nG0 X1\nM30\n", "a.nc").dialect, "rs274ngc");
}

TEST(DialectGuess, ACodeInACommentIsNoCode) {
  EXPECT_EQ(guess_dialect("(T1 M6)\nT1\nG0 X1\nM30\n", "a.nc").dialect, "grbl");
}

TEST(DialectGuess, AProgramNumberFirstLeansToFanuc) {
  const auto g = guess_dialect("O1234 (PART)\nG0 X1.\nM30\n", "a.nc");
  EXPECT_EQ(g.dialect, "fanuc");
  EXPECT_TRUE(says(g, "program number 'O1234'")) << g.reason;
}

TEST(DialectGuess, SemicolonCommentsRuleOutFanuc) {
  // Fanuc reads ';' as the end of a block: a ';' comment is not Fanuc's.
  EXPECT_EQ(guess_dialect("; a part\nO1000\nT1 M6\nG43 Z100 H1\nM30\n", "a.gcode").dialect,
            "rs274ngc");
}

TEST(DialectGuess, SemicolonEndingEveryBlockIsFanuc) {
  const auto g = guess_dialect("G0 X1;\nG1 X2 F100;\nG1 X3;\nM30;\n", "a.nc");
  EXPECT_EQ(g.dialect, "fanuc");
  EXPECT_TRUE(says(g, "end of block")) << g.reason;
}

TEST(DialectGuess, CodesGrblRefusesLeanToLinuxCnc) {
  // M6 and G43 (+4) against no end (+3).
  const auto g = guess_dialect("G0 X1\nT1 M6\nG43 H1\nG0 X2\n", "a.nc");
  EXPECT_EQ(g.dialect, "rs274ngc");
  EXPECT_TRUE(says(g, "G43, M6")) << g.reason;
  EXPECT_EQ(guess_dialect("G0 X1\nG81 Z-1 R1 F100\nG80\nM30\n", "a.nc").dialect, "rs274ngc");
  // One kind (+2) does not outweigh a missing end (+3): Grbl senders' test
  // files use G41 or M62 and end without M2.
  EXPECT_EQ(guess_dialect("G0 X1\nG81 Z-1 R1 F100\nG80\n", "a.nc").dialect, "grbl");
  EXPECT_EQ(guess_dialect("G64 P0.01\nG0 X1\nG1 X[2*3] F100\n", "a.nc").dialect, "rs274ngc");
}

TEST(DialectGuess, AToolWithoutAChangeLeansToGrbl) {
  // Grbl posts (Fusion 360's among them) write T1 and no M6.
  const auto g = guess_dialect("T1\nS5000 M3\nG0 X1\nM30\n", "a.nc");
  EXPECT_EQ(g.dialect, "grbl");
  EXPECT_TRUE(says(g, "no M6")) << g.reason;
}

TEST(DialectGuess, NoProgramEndLeansToGrbl) {
  EXPECT_EQ(guess_dialect("G0 X1\nG1 X2 F100\n", "a.nc").dialect, "grbl");
  EXPECT_EQ(guess_dialect("G0 X1\nG1 X2 F100\nM30\n", "a.nc").dialect, "rs274ngc");
  EXPECT_EQ(guess_dialect("G0 X1\nG1 X2 F100\nM2 (end)\n\n\n", "a.nc").dialect, "rs274ngc");
}

TEST(DialectGuess, TheExtensionIsAHint) {
  // '.ngc' (+4) outweighs the missing end (+3); '.gcode' (+1) tips a tie.
  EXPECT_EQ(guess_dialect("G0 X1\n", "dir.gcode/a.NGC").dialect, "rs274ngc");
  EXPECT_EQ(guess_dialect("G0 X1\nM30\n", "a.gcode").dialect, "grbl");
  EXPECT_EQ(guess_dialect("G0 X1\nT1\n", "a.tap").dialect, "grbl");
  EXPECT_EQ(guess_dialect("G0 X1\nM30\n", "a.tap").dialect, "rs274ngc");
  EXPECT_EQ(guess_dialect("G0 X1\nM30\n", "").dialect, "rs274ngc");
}

TEST(DialectGuess, ATieLeavesTheDefaultAndSaysSo) {
  // The extension '.tap' (+2) against a tool without M6 (+2).
  const auto g = guess_dialect("T1\nG0 X1\nM30\n", "a.tap");
  EXPECT_EQ(g.dialect, "rs274ngc");
  EXPECT_TRUE(says(g, "a tie")) << g.reason;
}

TEST(DialectGuess, TheReasonListsEachClueWithItsWeight) {
  const auto g = guess_dialect("G0 X1\n", "a.gcode");
  EXPECT_EQ(g.dialect, "grbl");
  EXPECT_EQ(g.reason,
            "grbl 4: no M2, M30 or '%' at its end (grbl +3); the extension '.gcode' (grbl +1)");
}

TEST(DialectGuess, NoClueIsTheDefault) {
  const auto g = guess_dialect("G0 X1\nM2\n", "a.nc");
  EXPECT_EQ(g.dialect, "rs274ngc");
  EXPECT_TRUE(says(g, "the default")) << g.reason;
}

TEST(DialectClues, TheEndIsFoundAmongTheLastBlocks) {
  EXPECT_TRUE(ends_with_program_end("G0 X1\nM30\n%\n"));
  EXPECT_TRUE(ends_with_program_end("G0 X1\nM02\n(done)\n\n"));
  EXPECT_TRUE(ends_with_program_end("G0 X1\nM2 G0 X0\n"));
  EXPECT_FALSE(ends_with_program_end("G0 X1\nM20\n"));
  EXPECT_FALSE(ends_with_program_end("M2\nG0 X1\nG0 X2\nG0 X3\n"));
  EXPECT_FALSE(ends_with_program_end(""));
  EXPECT_FALSE(ends_with_program_end(std::string(10000, 'G')));
}

TEST(DialectClues, LinesSplitIntoCodeAndComments) {
  const auto head = read_head("g0 x1 (a (nested) note) ; tail\nG1 X2;\n");
  ASSERT_GE(head.size(), 2u);
  EXPECT_EQ(head[0].code, "G0 X1");
  EXPECT_TRUE(head[0].semicolon_text);
  EXPECT_NE(head[0].comments.find("nested"), std::string::npos);
  EXPECT_NE(head[0].comments.find("tail"), std::string::npos);
  EXPECT_TRUE(head[1].bare_semicolon);
  EXPECT_EQ(read_head(std::string(300, '\n')).size(), kHeadLines);
}

}  // namespace
}  // namespace usina::gcode
