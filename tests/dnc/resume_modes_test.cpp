// The modes a restart writes back come from running the program before
// the start in its dialect (ProgramRunner::modes), not from reading its
// words: a subroutine that changes units, a computed G word, a frame moved
// inside a macro are seen as the control sees them. Each of these programs
// got a wrong restart from the word scan (G21 G90 where G20 G91 were in
// force: the rest of the program cut at the wrong size and in the wrong
// place).
#include <string>

#include <gtest/gtest.h>

#include "dnc/resume.hpp"

namespace usina::dnc {
namespace {

using K = gcode::ResumeStart::Kind;

std::string restart(const std::string& text, const std::string& dialect, gcode::ResumeStart at) {
  auto out = resume_program(text, dialect, at);
  EXPECT_TRUE(out.has_value()) << (out ? "" : out.error());
  return out.value_or("");
}

std::string refusal(const std::string& text, const std::string& dialect, gcode::ResumeStart at) {
  auto out = resume_program(text, dialect, at);
  EXPECT_FALSE(out.has_value()) << *out;
  return out ? "" : out.error();
}

// The preamble's lines, up to the start block (whose text is `first`).
std::string preamble(const std::string& restart_text, const std::string& first) {
  return restart_text.substr(0, restart_text.find("\n" + first) + 1);
}

TEST(ResumeModes, UnitsAndDistanceModeSetInASubroutineAreWrittenBack) {
  const std::string text =
      "o100 sub\nG20 G91\no100 endsub\nG21 G90 G54\nT1 M6\nS1000 M3\nG0 X0 Y0 Z5\n"
      "o100 call\nG1 X1 F10\nG1 X1\nG1 X1\nM2\n";
  const std::string p = preamble(restart(text, "rs274ngc", {K::Line, 10}), "G1 X1\nG1 X1\nM2");
  EXPECT_NE(p.find("G20 G17 G90"), std::string::npos) << p;
  EXPECT_NE(p.find("G54"), std::string::npos) << p;  // chosen at line 4, though in force already
  // Positions in the program's inches; G91 put back last, just before the start.
  EXPECT_NE(p.find("G0 X1 Y0\n"), std::string::npos) << p;
  EXPECT_TRUE(p.ends_with("G91\n")) << p;
}

TEST(ResumeModes, AFanucComputedGWordIsTheModeItComputes) {
  const std::string text =
      "%\nO1000\n#1=91\nG21 G#1 G54\nT1 M6\nS1000 M3\nG0 X10 Y0 Z5\nG1 X1 F100\n"
      "N50 G1 X1\nG1 X1\nM30\n%\n";
  const std::string p = preamble(restart(text, "fanuc", {K::NWord, 50}), "N50");
  EXPECT_NE(p.find("G00 X11. Y0."), std::string::npos) << p;  // the point reached, absolute
  EXPECT_TRUE(p.ends_with("G91\n")) << p;
}

TEST(ResumeModes, AProgramThatNeverChoseAWorkOffsetGetsNone) {
  // The machine keeps the system last in force (LinuxCNC's #5220): writing
  // G54 would move a program the operator ran in G55.
  const std::string text = "G21 G90\nG0 X0 Y0 Z5\nG1 X5 F100\nG1 X10\nM2\n";
  const std::string p = preamble(restart(text, "rs274ngc", {K::Line, 4}), "G1 X10");
  EXPECT_EQ(p.find("G54"), std::string::npos) << p;
}

TEST(ResumeModes, ALengthOffsetIsItsRegisterInEveryDialect) {
  const std::string ngc = "G21 G90 G54\nT2 M6\nG43 H2\nG0 X0 Y0 Z5\nG1 X5 F100\nG1 X10\nM2\n";
  EXPECT_NE(preamble(restart(ngc, "rs274ngc", {K::Line, 6}), "G1 X10").find("H2"),
            std::string::npos);
  const std::string nc =
      "%\nO1\nG21 G90 G54\nT2 M6\nG43 H2\nG0 X0 Y0 Z5\nG1 X5 F100\nN60 G1 X10\nM30\n%\n";
  EXPECT_NE(preamble(restart(nc, "fanuc", {K::NWord, 60}), "N60").find("H2"), std::string::npos);
  const std::string off = "G21 G90 G54\nT2 M6\nG43 H2\nG49\nG0 X0 Y0 Z5\nG1 X10 F100\nM2\n";
  EXPECT_EQ(preamble(restart(off, "rs274ngc", {K::Line, 6}), "G1 X10").find("G43"),
            std::string::npos);
}

TEST(ResumeModes, AFrameMovedInsideASubroutineIsRefused) {
  const std::string text =
      "o7 sub\nG92 X10\no7 endsub\nG21 G90\nG0 X0 Y0 Z5\no7 call\nG1 X20 F100\nM2\n";
  const std::string why = refusal(text, "rs274ngc", {K::Line, 7});
  EXPECT_NE(why.find("G92 or G52 offset"), std::string::npos) << why;
}

TEST(ResumeModes, AFanucRotationInAMacroIsRefused) {
  const std::string text =
      "%\nO1\nG21 G90 G54\n#1=68\nG0 X0 Y0 Z5\nG#1 X0 Y0 R30\nG1 X10 F100\nN80 G1 X20\nG69\n"
      "M30\n%\n";
  const std::string why = refusal(text, "fanuc", {K::NWord, 80});
  EXPECT_NE(why.find("rotation, mirror or scale"), std::string::npos) << why;
}

TEST(ResumeModes, ARomiScaleInForceIsRefused) {
  const std::string text =
      "N10 G71 G90#\nN20 X0 Y0 T01 M06;fresa d10#\nN30 G00 X0 Y0 Z5#\nN40 G72 K2#\n"
      "N50 G01 X10 F100#\nN60 G01 X20#\nN70 M30#\n";
  const std::string why = refusal(text, "romi", {K::NWord, 60});
  EXPECT_NE(why.find("rotation, mirror or scale"), std::string::npos) << why;
}

TEST(ResumeModes, ADynamicLengthOffsetIsRefused) {
  const std::string text = "G21 G90\nG43.1 Z5\nG0 X0 Y0 Z5\nG1 X5 F100\nG1 X10\nM2\n";
  const std::string why = refusal(text, "rs274ngc", {K::Line, 5});
  EXPECT_NE(why.find("G43.1 or G43.2"), std::string::npos) << why;
}

// G10 and offset parameters write values the modes do not show: a G10 in
// the main text is refused by its line (resume_point's frame_word); one run
// inside a subroutine or macro, or a parameter assignment, by the run.
TEST(ResumeModes, AG10RunInsideASubroutineIsRefused) {
  const std::string text =
      "o7 sub\nG10 L2 P1 X10\no7 endsub\nG21 G90 G54\nG0 X0 Y0 Z5\no7 call\n"
      "G1 X20 F100\nG1 X30\nM2\n";
  const std::string why = refusal(text, "rs274ngc", {K::Line, 8});
  EXPECT_NE(why.find("writes offsets before line 8"), std::string::npos) << why;
}

TEST(ResumeModes, AWorkOffsetParameterWrittenBeforeTheStartIsRefused) {
  const std::string text = "G21 G90\n#5221=10\nG54\nG0 X0 Y0 Z5\nG1 X5 F100\nG1 X10\nM2\n";
  const std::string why = refusal(text, "rs274ngc", {K::Line, 6});
  EXPECT_NE(why.find("work offset parameter"), std::string::npos) << why;
}

TEST(ResumeModes, AFanucG10InAMacroIsRefused) {
  const std::string text =
      "%\nO1\nG21 G90 G54\nG0 X0 Y0 Z5\nM98 P9\nG1 X10 F100\nN80 G1 X20\nM30\n"
      "O9\nG10 L2 P1 X5\nM99\n%\n";
  const std::string why = refusal(text, "fanuc", {K::NWord, 80});
  EXPECT_NE(why.find("writes offsets"), std::string::npos) << why;
}

TEST(ResumeModes, AG10SubroutineCalledOnlyAfterTheStartIsNoObstacle) {
  const std::string text =
      "o7 sub\nG10 L2 P1 X10\no7 endsub\nG21 G90 G54\nG0 X0 Y0 Z5\nG1 X20 F100\n"
      "G1 X30\no7 call\nM2\n";
  const std::string r = restart(text, "rs274ngc", {K::Line, 7});
  EXPECT_NE(r.find("o7 sub"), std::string::npos) << r;  // its definition goes with it
}

TEST(ResumeModes, AFanucSubprogramAfterTheEndRunsBeforeTheStart) {
  // O9 after M30 is called by M98 before N80: the run before the start
  // needs it (it was "no program O0009" when the text was cut at N80).
  const std::string text =
      "%\nO1\nG21 G90 G54\nT1 M6\nG0 X0 Y0 Z5.\nM98 P9\nG1 X1. F100\nN80 G1 X2.\nM30\n"
      "O9\nS800 M3\nG91\nM99\n%\n";
  const std::string r = restart(text, "fanuc", {K::NWord, 80});
  const std::string p = preamble(r, "N80");
  EXPECT_NE(p.find("S800 M03"), std::string::npos) << p;
  EXPECT_TRUE(p.ends_with("G91\n")) << p;
  EXPECT_NE(r.find("O9\nS800"), std::string::npos) << r;  // the subprogram stays in the restart
}

}  // namespace
}  // namespace usina::dnc
