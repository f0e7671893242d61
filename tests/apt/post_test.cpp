// usina apt PART.apt --post CONTROL -o FILE: the canon stream of an APT
// program written for a control by the posts `convert` uses.
#include "support/files.hpp"
#include "support/usina_process.hpp"

namespace usina::apt::test {
namespace {

using usina::test::quote;
using usina::test::TempDir;

constexpr const char* kContour =
    "PARTNO POSTED\nL1=LINE/0,0,0,10\nL2=LINE/0,5,10,5\nCUTTER/2\nFEDRAT/300\nFROM/-5,-5,0\n"
    "GO/TO,L1\nTLLFT,GOLFT/L1,PAST,L2\nEND\nFINI\n";

TEST(AptPost, WritesTheProgramForAControl) {
  const TempDir dir;
  const std::string f = dir.write("p.apt", kContour);
  const auto r =
      usina::test::usina("apt " + quote(f) + " --post fanuc -o " + quote(dir.path("p.nc")));
  EXPECT_EQ(r.status, 0) << r.err;
  const std::string nc = dir.read("p.nc");
  EXPECT_NE(nc.find("(POSTED)"), std::string::npos) << nc;
  EXPECT_NE(nc.find("G00 X-5. Y-5. Z0."), std::string::npos) << nc;
  EXPECT_NE(nc.find("G01 X-1. F300.\nY6.\n"), std::string::npos) << nc;
}

TEST(AptPost, CircleIsPostedAsAnArcOrWithChordsAsChords) {
  // Groover's contour (tests/programs/apt/README.md): GOFWD/C1 from (170,60)
  // counter-clockwise about (130,60) to (130,100): G03, I-40 J0 from the start.
  const std::string f = std::string(USINA_TEST_DIR) + "/programs/apt/groover_contour.apt";
  const auto r = usina::test::usina("apt " + quote(f) + " --post fanuc");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("Y60.\nG03 X130. Y100. I-40. J0.\nG01 X28.159\n"), std::string::npos)
      << r.out;
  const auto c = usina::test::usina("apt " + quote(f) + " --post fanuc --chords");
  EXPECT_EQ(c.status, 0) << c.err;
  EXPECT_EQ(c.out.find("G03"), std::string::npos) << c.out;
  EXPECT_NE(c.out.find("X170.002 Y61.965"), std::string::npos) << c.out;
}

TEST(AptPost, InchProgramIsPostedInMillimetres) {
  const TempDir dir;
  const std::string f = dir.write("p.apt", "FEDRAT/10\nFROM/0,0,0\nGOTO/1,0,0\nFINI\n");
  const auto r = usina::test::usina("apt " + quote(f) + " --units inch --post rs274ngc");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("X25.4"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("F254"), std::string::npos) << r.out;
}

TEST(AptPost, ProgramWithAnErrorWritesNothing) {
  const TempDir dir;
  const std::string f = dir.write("p.apt", "FROM/0,0,0\nGOTO/Q\nFINI\n");
  const auto r =
      usina::test::usina("apt " + quote(f) + " --post fanuc -o " + quote(dir.path("p.nc")));
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("E_APT_UNDEFINED_SYMBOL"), std::string::npos) << r.err;
  EXPECT_FALSE(usina::test::exists(dir.path("p.nc")));
}

TEST(AptPost, PostAndFormatOrPostOptionsWithoutPostAreUsageErrors) {
  const TempDir dir;
  const std::string f = dir.write("p.apt", kContour);
  EXPECT_EQ(usina::test::usina("apt " + quote(f) + " --post fanuc --format jsonl").status, 2);
  EXPECT_EQ(usina::test::usina("apt " + quote(f) + " --post fanuc --canonical").status, 2);
  const auto r =
      usina::test::usina("apt " + quote(f) + " --decimals 3 -o " + quote(dir.path("x.nc")));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--decimals goes with --post"), std::string::npos) << r.err;
  EXPECT_FALSE(usina::test::exists(dir.path("x.nc")));
}

}  // namespace
}  // namespace usina::apt::test
