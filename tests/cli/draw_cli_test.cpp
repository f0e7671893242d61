// usina draw as a user runs it: formats from the extension, the part and
// toolpath views, holes of G81, exit statuses, the golden SVG.
#include <cmath>
#include <sstream>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "support/usina_process.hpp"

namespace {

using usina::test::contains;
using usina::test::count;
using usina::test::exists;
using usina::test::quote;
using usina::test::slurp;
using usina::test::TempDir;
using usina::test::usina;
using Result = usina::test::Run;

const std::string kTests = USINA_TEST_DIR;
const std::string kExamples = std::string(USINA_TEST_DIR) + "/../examples";

// The contents of the <g id="LAYER"> group of an SVG.
std::string group(const std::string& svg, const std::string& layer) {
  const auto start = svg.find("<g id=\"" + layer + "\"");
  if (start == std::string::npos) return "";
  return svg.substr(start, svg.find("</g>", start) - start);
}

const std::string kBracket = kExamples + "/bracket.ngc";
const std::string kTools = " --tool-table " + quote(kExamples + "/tools.tbl");

TEST(DrawCli, BracketPartViewIsTheContourAndTwoHoles) {
  const TempDir s;
  const Result r = usina("draw " + quote(kBracket) + kTools + " -o " + s.path("b.svg"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  const std::string svg = s.read("b.svg");
  EXPECT_EQ(count(group(svg, "HOLES"), "<circle"), 2u) << svg;
  EXPECT_TRUE(contains(group(svg, "HOLES"), R"(<circle cx="12" cy="-15" r="3"/>)")) << svg;
  EXPECT_TRUE(contains(group(svg, "HOLES"), R"(<circle cx="28" cy="-15" r="3"/>)")) << svg;
  EXPECT_EQ(count(group(svg, "CONTOUR"), "<path"), 3u) << svg;  // three rounded corners
  EXPECT_TRUE(contains(group(svg, "CONTOUR"), R"(<line x1="0" y1="0" x2="34" y2="0"/>)"));
}

TEST(DrawCli, BracketToolpathViewHasATLayerAndTheCycleRapids) {
  const TempDir s;
  const Result r =
      usina("draw --view toolpath " + quote(kBracket) + kTools + " -o " + s.path("b.svg"));
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string svg = s.read("b.svg");
  EXPECT_FALSE(contains(svg, "id=\"CONTOUR\""));
  EXPECT_FALSE(contains(svg, "id=\"HOLES\""));
  EXPECT_EQ(count(group(svg, "TOOLPATH_T1"), "<path"), 3u) << svg;
  // The G81 rapids from one hole to the next.
  EXPECT_TRUE(contains(group(svg, "RAPID"), R"(x2="12" y2="-15")")) << svg;
}

TEST(DrawCli, BracketDxfHasTheLayersAndMillimetres) {
  const TempDir s;
  const Result r = usina("draw " + quote(kBracket) + kTools + " -o " + s.path("b.DXF"));
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string dxf = s.read("b.DXF");
  EXPECT_TRUE(contains(dxf, "$INSUNITS\n 70\n4\n")) << dxf.substr(0, 400);
  for (const char* layer : {"CONTOUR", "RAPID", "HOLES", "POCKETS", "DASHED"})
    EXPECT_TRUE(contains(dxf, std::string("\n  2\n") + layer + "\n")) << layer;
  EXPECT_EQ(count(dxf, "\nCIRCLE\n"), 2u);
  EXPECT_EQ(count(dxf, "\nARC\n"), 3u);
  EXPECT_TRUE(dxf.ends_with("EOF\n"));
}

TEST(DrawCli, PartViewIsTheProgrammedContourToolpathTheCompensatedOne) {
  const TempDir s;
  const std::string prog = s.write("comp.ngc",
                                   "G21 G90 G17\nT1 M6\nG0 X-10 Y-10\nG41 G1 X0 Y0 F100\n"
                                   "G1 X20\nG1 Y20\nG40 G1 X30 Y30\nM2\n");
  ASSERT_EQ(usina("draw " + prog + kTools + " -o " + s.path("p.svg")).status, 0);
  ASSERT_EQ(usina("draw --view toolpath " + prog + kTools + " -o " + s.path("t.svg")).status, 0);
  const std::string part = s.read("p.svg");
  const std::string path = s.read("t.svg");
  EXPECT_TRUE(contains(part, R"(<line x1="0" y1="0" x2="20" y2="0"/>)")) << part;
  // G41 keeps the 6 mm tool's centre 3 mm to the left of the +X move.
  EXPECT_TRUE(contains(path, R"(<line x1="0" y1="-3" x2="17" y2="-3"/>)")) << path;
}

// The cycle's feeds are left out; its rapids from hole to hole stay.
TEST(DrawCli, G81HolesAreCirclesOfTheToolAndTheirFeedsAreLeftOut) {
  const TempDir s;
  const std::string prog = s.write("holes.ngc",
                                   "G21 G90 G17\nT2 M6\nG0 X0 Y0 Z5\n"
                                   "G81 X10 Y10 Z-5 R1 F100\nX20\nX30 Y20\nG80\nM2\n");
  const Result r = usina("draw " + prog + kTools + " -o " + s.path("h.svg"));
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string svg = s.read("h.svg");
  EXPECT_EQ(count(group(svg, "HOLES"), R"(r="4.25")"), 3u) << svg;
  EXPECT_EQ(count(group(svg, "RAPID"), "<line"), 3u) << svg;
  EXPECT_TRUE(contains(group(svg, "RAPID"), R"(<line x1="0" y1="0" x2="10" y2="-10"/>)")) << svg;
  EXPECT_FALSE(contains(group(svg, "CONTOUR"), "<line")) << svg;
}

TEST(DrawCli, ProgramWithAnErrorDrawsWhatCameBeforeAndExitsOne) {
  const TempDir s;
  const std::string prog = s.write("bad.ngc", "G21 G90\nG1 X10 Y0 F100\nG1 X10 Y10\nG2 X12 R0.1\n");
  const Result r = usina("draw " + prog + " -o " + s.path("bad.svg"));
  EXPECT_EQ(r.status, 1);
  EXPECT_TRUE(contains(r.err, "bad.ngc:4:")) << r.err;
  EXPECT_TRUE(contains(r.err, "error:")) << r.err;
  const std::string svg = s.read("bad.svg");
  EXPECT_TRUE(contains(svg, R"(<line x1="10" y1="0" x2="10" y2="-10"/>)")) << svg;
  EXPECT_TRUE(svg.ends_with("</svg>\n"));
}

TEST(DrawCli, EmptyProgramIsAnEmptyDrawing) {
  const TempDir s;
  const Result r = usina("draw " + s.write("empty.ngc", "") + " -o " + s.path("e.svg"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(contains(s.read("e.svg"), R"(viewBox="-5 -5 10 10")"));
  ASSERT_EQ(usina("draw " + s.path("empty.ngc") + " -o " + s.path("e.dxf")).status, 0);
  EXPECT_TRUE(s.read("e.dxf").ends_with("EOF\n"));
  ASSERT_EQ(usina("draw " + s.path("empty.ngc") + " -o " + s.path("e.png")).status, 0);
  ASSERT_EQ(usina("draw " + s.path("empty.ngc") + " -o " + s.path("e.pdf")).status, 0);
}

TEST(DrawCli, ProgramOfRapidsOnlyDrawsTheRapids) {
  const TempDir s;
  const std::string prog = s.write("rapids.ngc", "G0 X10 Y10\nG0 X20\nM2\n");
  ASSERT_EQ(usina("draw " + prog + " -o " + s.path("r.svg")).status, 0);
  const std::string svg = s.read("r.svg");
  EXPECT_EQ(count(group(svg, "RAPID"), "<line"), 2u) << svg;
  EXPECT_FALSE(contains(group(svg, "CONTOUR"), "<line")) << svg;
}

TEST(DrawCli, StartIsWhereTheToolIsBeforeTheFirstMove) {
  const TempDir s;
  const std::string prog = s.write("inc.ngc", "G91 G1 X10 F100\nM2\n");
  const Result r = usina("draw --start 5,5,0 " + prog + " -o " + s.path("i.svg"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(contains(s.read("i.svg"), R"(<line x1="5" y1="-5" x2="15" y2="-5"/>)"));
}

TEST(DrawCli, BadStartExitsTwo) {
  const TempDir s;
  for (const char* bad : {"5", "1,2,3,4", "x,1,2", "1,,2"}) {
    const Result r = usina(std::string("draw --start ") + bad + " " + quote(kBracket) + " -o " +
                           s.path("x.svg"));
    EXPECT_EQ(r.status, 2) << bad;
    EXPECT_TRUE(contains(r.err, "usina: error: draw: --start")) << r.err;
  }
  EXPECT_FALSE(exists(s.path("x.svg")));
}

// Width and height from a PNG's IHDR chunk.
std::pair<unsigned, unsigned> png_size(const std::string& png) {
  auto be32 = [&](std::size_t at) {
    unsigned v = 0;
    for (std::size_t i = 0; i < 4; ++i)
      v = (v << 8) | static_cast<unsigned char>(png.at(at + i));
    return v;
  };
  return {be32(16), be32(20)};
}

TEST(DrawCli, PngHasTheAskedOrDefaultSize) {
  const TempDir s;
  ASSERT_EQ(usina("draw --size 320x200 " + quote(kBracket) + " -o " + s.path("a.png")).status, 0);
  const std::string png = s.read("a.png");
  ASSERT_TRUE(png.starts_with("\x89PNG\r\n\x1a\n"));
  EXPECT_EQ(png_size(png), (std::pair<unsigned, unsigned>{320, 200}));
  ASSERT_EQ(usina("draw " + quote(kBracket) + " -o " + s.path("b.png")).status, 0);
  EXPECT_EQ(png_size(s.read("b.png")), (std::pair<unsigned, unsigned>{1600, 1200}));
}

TEST(DrawCli, BadSizeOrSizeOfAnotherFormatExitsTwo) {
  const TempDir s;
  for (const char* bad : {"0x10", "10", "10x10x10", "1.5x10", "100000x100000"}) {
    const Result r =
        usina(std::string("draw --size ") + bad + " " + quote(kBracket) + " -o " + s.path("x.png"));
    EXPECT_EQ(r.status, 2) << bad;
    EXPECT_TRUE(contains(r.err, "--size")) << r.err;
  }
  const Result r = usina("draw --size 10x10 " + quote(kBracket) + " -o " + s.path("x.svg"));
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(contains(r.err, "PNG")) << r.err;
}

TEST(DrawCli, PdfIsAPdf) {
  const TempDir s;
  ASSERT_EQ(usina("draw " + quote(kBracket) + kTools + " -o " + s.path("b.pdf")).status, 0);
  EXPECT_TRUE(s.read("b.pdf").starts_with("%PDF"));
}

TEST(DrawCli, UnknownExtensionExitsTwoAndWritesNothing) {
  const TempDir s;
  for (const char* name : {"x.txt", "x", "dir.svg/x"}) {
    const Result r = usina("draw " + quote(kBracket) + " -o " + s.path(name));
    EXPECT_EQ(r.status, 2) << name;
    EXPECT_TRUE(contains(r.err, "usina: error: draw: cannot tell the format")) << r.err;
    EXPECT_FALSE(exists(s.path(name)));
  }
}

TEST(DrawCli, UnreadableProgramExitsTwoAndWritesNothing) {
  const TempDir s;
  const Result r = usina("draw /nonexistent/usina/p.ngc -o " + s.path("x.svg"));
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(contains(r.err, "cannot read")) << r.err;
  EXPECT_FALSE(exists(s.path("x.svg")));
}

TEST(DrawCli, UnwritableOutputExitsTwo) {
  const TempDir s;
  for (const char* ext : {"svg", "dxf", "png", "pdf"}) {
    const Result r =
        usina("draw " + quote(kBracket) + " -o /nonexistent/usina/x." + std::string(ext));
    EXPECT_EQ(r.status, 2) << ext;
    EXPECT_TRUE(contains(r.err, "usina: error: draw: cannot write /nonexistent/usina/x.")) << r.err;
  }
}

TEST(DrawCli, MissingOutputOrBadViewIsAUsageError) {
  const TempDir s;
  EXPECT_NE(usina("draw " + quote(kBracket)).status, 0);
  EXPECT_NE(usina("draw --view side " + quote(kBracket) + " -o " + s.path("x.svg")).status, 0);
  EXPECT_FALSE(exists(s.path("x.svg")));
}

TEST(DrawCli, HelpListsTheOptions) {
  const Result r = usina("draw --help");
  ASSERT_EQ(r.status, 0);
  for (const char* opt :
       {"--output", "--view", "--start", "--size", "--tolerance", "--dialect", "--tool-table"})
    EXPECT_TRUE(contains(r.out, opt)) << opt;
}

// A circle of radius 50 as 3,600 G1 moves of 0.087 mm: what CAM writes for
// an engraved curve.
std::string circle_of_moves() {
  std::string prog = "G21 G90 G17\nG0 X50 Y0\nG1 Z-1 F300\n";
  for (int i = 1; i <= 3600; ++i) {
    const double a = i * 3.14159265358979323846 / 1800.0;
    prog +=
        "G1 X" + std::to_string(50 * std::cos(a)) + " Y" + std::to_string(50 * std::sin(a)) + "\n";
  }
  return prog + "M2\n";
}

TEST(DrawCli, MovesWithinTheToleranceAreDrawnAsOneLine) {
  // A chord 0.01 mm from a circle of radius 50 is 2 mm long: 23 moves.
  const TempDir s;
  const std::string prog = s.write("circle.ngc", circle_of_moves());
  ASSERT_EQ(usina("draw " + prog + " -o " + s.path("default.dxf")).status, 0);
  ASSERT_EQ(usina("draw --tolerance 0 " + prog + " -o " + s.path("exact.dxf")).status, 0);
  ASSERT_EQ(usina("draw --tolerance 0.1 " + prog + " -o " + s.path("coarse.dxf")).status, 0);
  const std::size_t exact = count(s.read("exact.dxf"), "\nLINE\n");
  const std::size_t fine = count(s.read("default.dxf"), "\nLINE\n");
  const std::size_t coarse = count(s.read("coarse.dxf"), "\nLINE\n");
  EXPECT_EQ(exact, 3601u) << "every move and the rapid to the start";
  EXPECT_GE(fine, 3600u / 24);
  EXPECT_LE(fine, 3600u / 12);
  EXPECT_LT(coarse, fine / 2) << fine << " " << coarse;
}

TEST(DrawCli, AToleranceThatIsNoLengthIsAUsageError) {
  const TempDir s;
  for (const char* bad : {"-0.01", "1.5", "nan", "inf", "x", "1e400"}) {
    const Result r = usina("draw --tolerance " + std::string(bad) + " " + quote(kBracket) + " -o " +
                           s.path("x.svg"));
    EXPECT_EQ(r.status, 2) << bad;
    EXPECT_FALSE(r.err.empty()) << bad;
    EXPECT_FALSE(exists(s.path("x.svg"))) << bad;
  }
}

// tests/golden/draw_small.svg, checked by hand (see its "golden:" comment,
// which is dropped before the comparison). To regenerate after a change:
//   usina draw tests/programs/rs274ngc/draw_small.ngc --tool-table
//   examples/tools.tbl -o /tmp/s.svg, diff, check the difference by hand.
TEST(DrawCli, SmallProgramMatchesTheGoldenSvg) {
  const TempDir s;
  const Result r = usina("draw " + quote(kTests + "/programs/rs274ngc/draw_small.ngc") + kTools +
                         " -o " + s.path("small.svg"));
  ASSERT_EQ(r.status, 0) << r.err;
  std::istringstream golden(slurp(kTests + "/golden/draw_small.svg"));
  std::string want;
  for (std::string line; std::getline(golden, line);)
    if (!line.starts_with("<!-- golden:")) want += line + "\n";
  EXPECT_EQ(s.read("small.svg"), want);
}

}  // namespace
