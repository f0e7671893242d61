// Restart programs (docs/resume.md): golden files for each dialect
// (tests/dnc/resume/README.md says how they were checked) and the starts
// that are refused, with their reasons.
#include "dnc/resume.hpp"

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "support/dialect_run.hpp"

namespace usina::dnc {
namespace {

std::string dir() {
  return std::string(USINA_TEST_DIR) + "/dnc/resume/";
}

std::string read(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string restart(const std::string& file, const std::string& dialect, const char* start) {
  auto s = gcode::parse_start_block(start);
  EXPECT_TRUE(s.has_value());
  auto out = resume_program(read(dir() + file), dialect, *s);
  EXPECT_TRUE(out.has_value()) << (out ? "" : out.error());
  return out.value_or("");
}

std::string restart_tool(const std::string& file, const std::string& dialect, long tool) {
  auto out = resume_program(read(dir() + file), dialect, {gcode::ResumeStart::Kind::Tool, tool});
  EXPECT_TRUE(out.has_value()) << (out ? "" : out.error());
  return out.value_or("");
}

void golden(const std::string& name, const std::string& got) {
  const std::string path = dir() + name;
  if (std::getenv("USINA_UPDATE_GOLDEN") != nullptr) {
    std::ofstream(path, std::ios::binary) << got;
  }
  EXPECT_EQ(read(path), got) << "golden " << path;
}

std::string refusal(const std::string& file, const std::string& dialect, gcode::ResumeStart start) {
  auto out = resume_program(read(dir() + file), dialect, start);
  EXPECT_FALSE(out.has_value());
  return out ? "" : out.error();
}

using K = gcode::ResumeStart::Kind;

TEST(ResumeGolden, Rs274ngcFromLine) {
  golden("rs274ngc-line11.resume", restart("rs274ngc.ngc", "rs274ngc", "11"));
}

TEST(ResumeGolden, Rs274ngcFromTool) {
  golden("rs274ngc-tool2.resume", restart_tool("rs274ngc.ngc", "rs274ngc", 2));
}

TEST(ResumeGolden, FanucFromNWord) {
  golden("fanuc-N90.resume", restart("fanuc.nc", "fanuc", "N90"));
}

TEST(ResumeGolden, RomiFromNWord) {
  golden("romi-N110.resume", restart("romi.nc", "romi", "N0110"));
}

TEST(ResumeGolden, GrblFromLine) {
  golden("grbl-line7.resume", restart("grbl.nc", "grbl", "7"));
}

TEST(ResumeGolden, FanucFromTool) {
  golden("fanuc-tools-tool2.resume", restart_tool("fanuc-tools.nc", "fanuc", 2));
}

TEST(ResumeGolden, RomiFromTool) {
  golden("romi-tools-tool2.resume", restart_tool("romi-tools.nc", "romi", 2));
}

// A restart is a program like any other: its own dialect reads it with no
// error (romi's restart once wrote "T1 M06" without the diameter its
// reader takes from the change's comment, and was refused).
TEST(ResumeGolden, EveryRestartReadsBackInItsDialect) {
  const std::pair<const char*, const char*> files[] = {
      {"rs274ngc-line11.resume", "rs274ngc"}, {"rs274ngc-tool2.resume", "rs274ngc"},
      {"fanuc-N90.resume", "fanuc"},          {"fanuc-tools-tool2.resume", "fanuc"},
      {"romi-N110.resume", "romi"},           {"romi-tools-tool2.resume", "romi"},
      {"grbl-line7.resume", "grbl"}};
  for (const auto& [file, dialect] : files) {
    const auto r = gcode::dialect_test::run_in(dialect, read(dir() + file));
    EXPECT_TRUE(r->ok) << file << ": " << r->first_error_text();
  }
}

TEST(ResumeGolden, TheRestIsTheProgramsOwnBytes) {
  const std::string text = read(dir() + "fanuc.nc");
  const std::string out = restart("fanuc.nc", "fanuc", "N90");
  const std::string rest = text.substr(text.find("N90 "));
  ASSERT_GE(out.size(), rest.size());
  EXPECT_EQ(out.substr(out.size() - rest.size()), rest);
  EXPECT_EQ(out.rfind("%\nO1234", 0), 0u) << "the tape opens with % and the O number";
}

TEST(ResumeRefused, InsideAFanucWhileLoop) {
  const std::string why = refusal("fanuc.nc", "fanuc", {K::NWord, 160});
  EXPECT_NE(why.find("WHILE"), std::string::npos) << why;
}

TEST(ResumeRefused, OnACannedCycleContinuation) {
  const std::string why = refusal("fanuc.nc", "fanuc", {K::NWord, 120});
  EXPECT_NE(why.find("canned cycle G81"), std::string::npos) << why;
}

TEST(ResumeRefused, PastTheEnd) {
  EXPECT_NE(refusal("grbl.nc", "grbl", {K::Line, 99}).find("past the end"), std::string::npos);
  EXPECT_NE(refusal("fanuc.nc", "fanuc", {K::Line, 22}).find("after the program's end"),
            std::string::npos);
}

TEST(ResumeRefused, AToolNeverUsed) {
  EXPECT_NE(refusal("rs274ngc.ngc", "rs274ngc", {K::Tool, 7}).find("tool T7 is never"),
            std::string::npos);
  // Grbl 1.1 has no tool change (M6 is its error 20): no start by tool.
  EXPECT_NE(refusal("grbl.nc", "grbl", {K::Tool, 1}).find("tool T1 is never"), std::string::npos);
}

TEST(ResumeRefused, AnUnknownNWord) {
  EXPECT_NE(refusal("fanuc.nc", "fanuc", {K::NWord, 95}).find("no block N95"), std::string::npos);
}

TEST(ResumeRefused, InsideAnOWordSubroutineOrLoop) {
  const std::string text =
      "o<peck> sub\nG1 Z-1 F100\nG0 Z1\no<peck> endsub\nG0 X0 Y0 Z5\n"
      "o100 repeat [3]\nG1 X1 F100\no100 endrepeat\no<peck> call\nM2\n";
  auto sub = resume_program(text, "rs274ngc", {K::Line, 2});
  ASSERT_FALSE(sub);
  EXPECT_NE(sub.error().find("inside a subroutine"), std::string::npos) << sub.error();
  auto loop = resume_program(text, "rs274ngc", {K::Line, 7});
  ASSERT_FALSE(loop);
  EXPECT_NE(loop.error().find("REPEAT"), std::string::npos) << loop.error();
  auto call = resume_program(text, "rs274ngc", {K::Line, 9});
  ASSERT_TRUE(call) << call.error();
  EXPECT_NE(call->find("o<peck> sub\n"), std::string::npos) << "its definition comes along";
}

TEST(ResumeRefused, InsideARomiSubOrRepeatedSection) {
  const std::string text =
      "N0010 G71#\nN0020 G00 X0 Y0 Z5#\nN0030 G01 X10 F100#\nN0040 X20#\n"
      "N0050 (RPT N0030,N0040,2)#\nN0060 M02#\n";
  auto in = resume_program(text, "romi", {K::NWord, 40});
  ASSERT_FALSE(in);
  EXPECT_NE(in.error().find("RPT"), std::string::npos) << in.error();
}

TEST(ResumeRefused, InsideALoopAFanucGotoCloses) {
  const std::string text =
      "%\nO1000\nG21 G90 G54\nT1 M6\nS1000 M3\nG0 X0 Y0 Z5\n#1=0\nN10 G1 X#1 F100\n"
      "G1 Y10\n#1=#1+5\nIF [#1 LT 20] GOTO 10\nG0 Z5\nM30\n%\n";
  for (const long line : {8L, 9L, 11L}) {
    auto in = resume_program(text, "fanuc", {K::Line, line});
    ASSERT_FALSE(in) << "line " << line;
    EXPECT_NE(in.error().find("the loop the GOTO at line 11 closes"), std::string::npos)
        << in.error();
  }
  auto after = resume_program(text, "fanuc", {K::Line, 12});
  EXPECT_TRUE(after) << after.error();
}

TEST(ResumeRefused, WhereAFanucGotoJumpsOverOrIsComputed) {
  const std::string text =
      "%\nO1000\nG21 G90 G54\nT1 M6\nS1000 M3\nG0 X0 Y0 Z5\nIF [#500 EQ 1] GOTO 20\n"
      "G1 X10 F100 (GOTO is only a word in this comment)\nN20 G1 Y10 F100\nG0 Z5\nM30\n%\n";
  auto over = resume_program(text, "fanuc", {K::Line, 8});
  ASSERT_FALSE(over);
  EXPECT_NE(over.error().find("the blocks the GOTO at line 7 jumps over"), std::string::npos)
      << over.error();
  auto target = resume_program(text, "fanuc", {K::Line, 9});
  EXPECT_TRUE(target) << target.error();
  const std::string computed =
      "%\nO1000\nG21 G90 G54\nT1 M6\nS1000 M3\nG0 X0 Y0 Z5\nG1 X10 F100\nGOTO #500\n"
      "N20 G1 Y10\nM30\n%\n";
  auto anywhere = resume_program(computed, "fanuc", {K::Line, 7});
  ASSERT_FALSE(anywhere);
  EXPECT_NE(anywhere.error().find("computed"), std::string::npos) << anywhere.error();
}

TEST(ResumeRefused, InsideALoopARomiGotoCloses) {
  const std::string text =
      "N0010 G71#\nN0020 G00 X0 Y0 Z5#\nN0025 (P1 = 0)#\nN0030 G01 X10 F100#\n"
      "N0040 (P1 = P1 + 1)#\nN0050 (IF P1 LT 3 GOTO N0030)#\nN0060 G00 Z5#\nN0070 M02#\n";
  auto in = resume_program(text, "romi", {K::NWord, 30});
  ASSERT_FALSE(in);
  EXPECT_NE(in.error().find("the loop the GOTO at line 6 closes"), std::string::npos) << in.error();
  auto after = resume_program(text, "romi", {K::NWord, 60});
  EXPECT_TRUE(after) << after.error();
}

TEST(ResumeRefused, ManyJumpsOverOneSpanMarkEachLineOnce) {
  // 50,000 jumps back over the whole program: each line is marked once, not
  // once a jump (the scan of an upload stays linear).
  std::string text = "%\nO1000\nN1 G0 X0 Y0 Z5\n";
  for (int i = 0; i < 50000; ++i)
    text += "IF [#1 GT 1] GOTO 1\n";
  text += "M30\n%\n";
  auto first = resume_program(text, "fanuc", {K::Line, 3});
  ASSERT_FALSE(first);
  EXPECT_NE(first.error().find("the loop the GOTO at line 4 closes"), std::string::npos)
      << first.error();
  auto last = resume_program(text, "fanuc", {K::Line, 50003});
  ASSERT_FALSE(last);
  EXPECT_NE(last.error().find("the loop the GOTO at line 50003 closes"), std::string::npos)
      << last.error();
}

TEST(ResumeRefused, AfterAFrameChange) {
  const std::string text = "G0 X0 Y0 Z5\nG92 X10\nG1 X20 F100\nM2\n";
  auto out = resume_program(text, "rs274ngc", {K::Line, 3});
  ASSERT_FALSE(out);
  EXPECT_NE(out.error().find("G92 at line 2"), std::string::npos) << out.error();
}

TEST(ResumeStartBlock, LineNumberOrNWord) {
  EXPECT_EQ(gcode::parse_start_block("120")->kind, K::Line);
  EXPECT_EQ(gcode::parse_start_block("N120")->kind, K::NWord);
  EXPECT_EQ(gcode::parse_start_block("n0120")->value, 120);
  EXPECT_FALSE(gcode::parse_start_block("N"));
  EXPECT_FALSE(gcode::parse_start_block("12x"));
  EXPECT_FALSE(gcode::parse_start_block("-3"));
}

}  // namespace
}  // namespace usina::dnc
