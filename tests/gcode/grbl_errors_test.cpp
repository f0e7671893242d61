// Every Grbl error number the grbl dialect reports, each from the smallest
// block that makes Grbl 1.1 answer it (gnea/grbl gcode.c, protocol.c,
// system.c, settings.c; docs/grbl.md §5), and Grbl's line reader.
#include <algorithm>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "canon/toolpath.hpp"
#include "core/source.hpp"
#include "gcode/dialect.hpp"
#include "gcode/dialects/grbl.hpp"

namespace usina::gcode {
namespace {

struct Run {
  core::SourceManager sources;
  core::DiagnosticList diags;
  canon::Toolpath path;
  bool ok = false;

  // (line, Grbl number) of every E_GRBL, in order.
  std::vector<std::pair<std::uint32_t, int>> errors() const {
    std::vector<std::pair<std::uint32_t, int>> out;
    for (const core::Diagnostic& d : diags.all()) {
      if (d.code != core::Code::GrblError) continue;
      const std::size_t at = d.message.find("error:");
      out.emplace_back(d.loc.line, std::stoi(d.message.substr(at + 6)));
    }
    return out;
  }
};

std::unique_ptr<Run> run_grbl(const std::string& text, const std::vector<std::string>& opts = {}) {
  auto r = std::make_unique<Run>();
  const std::uint32_t id = r->sources.add(core::SourceFile::from_string("t.nc", text));
  const Dialect* d = find_dialect("grbl");
  EXPECT_NE(d, nullptr);
  OptionValues values;
  EXPECT_FALSE(resolve_options(*d, opts, values).has_value());
  auto runner = d->make_runner(RunContext{r->sources, {}, std::move(values), r->path, r->diags});
  r->ok = runner->run(id);
  return r;
}

// The Grbl number of the one error `block` raises (after `setup`, which
// must raise none), or 0.
int number_of(const std::string& block, const std::string& setup = "") {
  const std::uint32_t line =
      static_cast<std::uint32_t>(std::count(setup.begin(), setup.end(), '\n')) + 1;
  auto r = run_grbl(setup + block + "\n");
  const auto e = r->errors();
  EXPECT_LE(e.size(), 1u) << block;
  if (e.empty()) return 0;
  EXPECT_EQ(e[0].first, line) << block;
  return e[0].second;
}

TEST(GrblErrors, WordsAndNumbers) {
  EXPECT_EQ(number_of("#1=5"), 1);
  EXPECT_EQ(number_of("G0 X1 %"), 1);
  EXPECT_EQ(number_of("G0 X[1+2]"), 2);
  EXPECT_EQ(number_of("G0 X#1"), 2);
  EXPECT_EQ(number_of("G0 X"), 2);
  EXPECT_EQ(number_of("G0 X-.5"), 0);
  EXPECT_EQ(number_of("F-5"), 4);
  EXPECT_EQ(number_of("S-1"), 4);
  EXPECT_EQ(number_of("G0 X1 X2"), 25);
  EXPECT_EQ(number_of("N10000001 G0 X1"), 27);
  EXPECT_EQ(number_of("T256"), 38);
  EXPECT_EQ(number_of("T255"), 0);
}

TEST(GrblErrors, UnsupportedCommandsAndLetters) {
  for (const char* b : {"G81 X1 Y1 Z-1 R1 F100", "G83 Z-1 R1 Q1 F100", "G98", "M6 T1", "G43 H1",
                        "G41 D1", "G64", "G90.1", "G38.1 Z-1 F10", "G92.2", "G61.1", "M7", "M56",
                        "G0 A10", "O100", "G10 L1 P1 X0", "G10 L2 P1 R5 X0"}) {
    EXPECT_EQ(number_of(b), 20) << b;
  }
}

TEST(GrblErrors, M7NeedsTheBuildOption) {
  auto r = run_grbl("M7\n", {"grbl_m7=on"});
  EXPECT_TRUE(r->errors().empty());
}

TEST(GrblErrors, FractionsAndGroups) {
  EXPECT_EQ(number_of("G59.1"), 23);
  EXPECT_EQ(number_of("G1.5 X1 F10"), 23);
  EXPECT_EQ(number_of("M3.1"), 23);
  EXPECT_EQ(number_of("G17 G18"), 21);
  EXPECT_EQ(number_of("M3 M5"), 21);
  EXPECT_EQ(number_of("M8 M9"), 21);
  // Two axis commands: Grbl finds the axis conflict before the group.
  EXPECT_EQ(number_of("G0 G1 X1"), 24);
  EXPECT_EQ(number_of("G0 G92 X0"), 24);
  EXPECT_EQ(number_of("G28 G1 X1 F10"), 24);
}

TEST(GrblErrors, FeedRate) {
  EXPECT_EQ(number_of("G1 X10"), 22);
  EXPECT_EQ(number_of("G1 X10 F100"), 0);
  EXPECT_EQ(number_of("G93 G1 X10", "G1 X1 F100\n"), 22);
  EXPECT_EQ(number_of("G1 X10", "G1 X1 F100\nG93 G1 X2 F2\nG94\n"),
            22);  // back from G93: F undefined
  EXPECT_EQ(number_of("G38.2 Z-5"), 22);
  EXPECT_EQ(number_of("G0 X10"), 0);  // G0 needs none
}

TEST(GrblErrors, MissingWords) {
  EXPECT_EQ(number_of("G4"), 28);
  EXPECT_EQ(number_of("G4 P0.5"), 0);
  EXPECT_EQ(number_of("G10 X0"), 28);
  EXPECT_EQ(number_of("G10 L2 P7 X0"), 29);
  EXPECT_EQ(number_of("G10 L20 P1"), 26);
  EXPECT_EQ(number_of("G92"), 26);
  EXPECT_EQ(number_of("G2 I5 F100"), 26);
  EXPECT_EQ(number_of("G38.2 F100"), 26);
  EXPECT_EQ(number_of("G2 Z1 I5 F100"), 32);
  EXPECT_EQ(number_of("G2 X1 F100"), 35);
  EXPECT_EQ(number_of("G18 G2 X1 Z1 J1 F100"), 35);  // G18: the offsets are K and I
}

TEST(GrblErrors, ModesAndUnusedWords) {
  EXPECT_EQ(number_of("G53 X0", "G2 X1 Y1 R1 F100\n"), 30);
  EXPECT_EQ(number_of("G53 G0 X0"), 0);
  EXPECT_EQ(number_of("X1", "G80\n"), 31);
  EXPECT_EQ(number_of("G92 X1", "G80\n"), 31);
  EXPECT_EQ(number_of("G0 X1 R5"), 36);
  EXPECT_EQ(number_of("G0 X1 P5"), 36);
  EXPECT_EQ(number_of("G2 X10 R5 I5 F100"), 36);
  EXPECT_EQ(number_of("G43.1 X1"), 37);
  // Accepted; the interpreter then reads G43.1's Z as LinuxCNC does (docs/grbl.md).
  EXPECT_EQ(number_of("G43.1 Z1", "G0 X0\n"), 0);
}

TEST(GrblErrors, ArcGeometryFromTheInterpreter) {
  EXPECT_EQ(number_of("G2 X10 Y0 R2 F100"), 34);
  EXPECT_EQ(number_of("G2 X0 Y0 R2 F100"), 33);   // R arc ending at its start
  EXPECT_EQ(number_of("G2 X10 Y1 I5 F100"), 33);  // 0.099 mm off: the interpreter's own error
  EXPECT_EQ(number_of("G38.2 X0 F100"), 33);      // probe to where it is
}

TEST(GrblErrors, ArcToleranceIsGrbls) {
  // 0.004 mm off: inside Grbl's 0.005 mm.
  EXPECT_EQ(number_of("G2 X10.004 Y0 I5 F100"), 0);
  // R 1000: 0.8 mm off is 0.08 % of the radius but above Grbl's 0.5 mm
  // ceiling; LinuxCNC (0.1 % with no ceiling) accepts it.
  EXPECT_EQ(number_of("G2 X2000.8 Y0 I1000 F100"), 33);
  // R 100: 0.05 mm off is above 0.005 mm but within 0.1 % of 100 mm.
  EXPECT_EQ(number_of("G2 X200.05 Y0 I100 F100"), 0);
  // R 10: 0.02 mm off: LinuxCNC's 0.028 mm accepts it, Grbl does not.
  EXPECT_EQ(number_of("G2 X20.02 Y0 I10 F100"), 33);
}

TEST(GrblErrors, SystemCommands) {
  EXPECT_EQ(number_of("$99999=1"), 3);
  EXPECT_EQ(number_of("$7=1"), 3);  // not a Grbl 1.1 setting
  EXPECT_EQ(number_of("$Q"), 3);
  EXPECT_EQ(number_of("$100=-1"), 4);
  EXPECT_EQ(number_of("$H"), 5);
  EXPECT_EQ(number_of("$0=2"), 6);
  EXPECT_EQ(number_of("$20=1"), 10);
  EXPECT_EQ(number_of("$20=1", "$22=1\n"), 0);
  EXPECT_EQ(number_of("$J=G91 X5 M3 F100"), 16);
  EXPECT_EQ(number_of("$J=G91 X5 S100 F100"), 16);
  EXPECT_EQ(number_of("$J"), 16);
  EXPECT_EQ(number_of("$J=G91 X5"), 22);
  EXPECT_EQ(number_of("$N0=G81"), 20);
  EXPECT_EQ(number_of("$N0=G20 G54"), 0);
  for (const char* b : {"$", "$$", "$#", "$G", "$I", "$N", "$X", "$I=my mill"})
    EXPECT_EQ(number_of(b), 0) << b;
}

TEST(GrblErrors, LineOverflow) {
  const std::string line79 = "G0X1." + std::string(74, '0');
  EXPECT_EQ(line79.size(), 79u);
  EXPECT_NE(number_of(line79), 11);
  EXPECT_EQ(number_of(line79 + "1"), 11);
  // Blanks and comments do not count.
  EXPECT_NE(number_of("G0 X1 (" + std::string(100, 'c') + ")"), 11);
}

TEST(GrblErrors, TextAndMappingTables) {
  EXPECT_EQ(grbl::error_text(20), "Unsupported command");
  EXPECT_EQ(grbl::error_text(33), "Invalid gcode ID:33");
  EXPECT_EQ(grbl::error_text(18), "");
  EXPECT_EQ(grbl::error_text(99), "");
  EXPECT_EQ(grbl::error_for(core::Code::ArcRadiusTooSmall), 34);
  EXPECT_EQ(grbl::error_for(core::Code::Message), 0);
  EXPECT_EQ(grbl::error_message(22, "x"), "grbl error:22 (Undefined feed rate): x");
}

TEST(GrblLines, StripLikeGrblsLineReader) {
  const grbl::StrippedLine s = grbl::strip_line("g1 x 1 0 (cmt) /y2 ; rest");
  EXPECT_EQ(s.text, "G1X10Y2");
  EXPECT_EQ(s.cols.front(), 1u);
  EXPECT_EQ(s.cols.back(), 18u);
  EXPECT_EQ(s.blanked.size(), std::string("g1 x 1 0 (cmt) /y2 ; rest").size());
  EXPECT_EQ(s.blanked.substr(0, 8), "G1 X 1 0");
  EXPECT_EQ(grbl::strip_line("(unclosed G1 X1").text, "");
  EXPECT_EQ(grbl::strip_line("G0 X1 (a;b) Y2").text, "G0X1Y2");
  EXPECT_EQ(grbl::strip_line("G0 X1 (\xC3\xA9t\xC3\xA9)").text, "G0X1");
  EXPECT_EQ(grbl::strip_line("G0 X1 (done!)").realtime_col, 12u);
}

TEST(GrblLines, ReadWordsLikeReadFloat) {
  std::vector<grbl::Word> w;
  const grbl::StrippedLine s = grbl::strip_line("G1X+1.5Y-.25Z3.");
  ASSERT_FALSE(grbl::read_words(s.text, s.cols, w));
  ASSERT_EQ(w.size(), 4u);
  EXPECT_DOUBLE_EQ(w[1].value, 1.5);
  EXPECT_DOUBLE_EQ(w[2].value, -0.25);
  EXPECT_DOUBLE_EQ(w[3].value, 3.0);
  const grbl::StrippedLine bad = grbl::strip_line("G1 X1.2.3");
  auto f = grbl::read_words(bad.text, bad.cols, w);
  ASSERT_TRUE(f);
  EXPECT_EQ(f->number, 1);  // "X1.2" then ".3" where a letter must be
}

}  // namespace
}  // namespace usina::gcode
