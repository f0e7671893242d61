// Contouring (research/apt.md §5): GO/ against one to three surfaces, the
// motions along a line or circle drive surface to a check surface (TO, ON,
// PAST, TANTO, n INTOF, the implicit check surface), the cutter offset and
// the circle's segmentation within INTOL/OUTTOL; values worked by hand.
#include "apt/contour.hpp"

#include <cmath>

#include "apt_run.hpp"

namespace usina::apt::test {
namespace {

// The points of the motion records (5000) of the statement on `line`.
std::vector<core::Vec3> points_of(const AptRun& r, std::uint32_t line) {
  std::vector<core::Vec3> out;
  for (const ClRecord& rec : r.result.records)
    if (rec.cls == cls::kMotion && rec.src.line == line)
      for (std::size_t i = 2; i + 2 < rec.words.size(); i += 3)
        out.push_back({rec.words[i].real, rec.words[i + 1].real, rec.words[i + 2].real});
  return out;
}

void expect_at(const core::Vec3& p, double x, double y, double z) {
  EXPECT_NEAR(p.x, x, 1e-7);
  EXPECT_NEAR(p.y, y, 1e-7);
  EXPECT_NEAR(p.z, z, 1e-7);
}

// The end of the statement on `line` (the last point of its records).
core::Vec3 end_of(const AptRun& r, std::uint32_t line) {
  const auto p = points_of(r, line);
  if (p.empty()) {
    ADD_FAILURE() << "no motion on line " << line;
    return {};
  }
  return p.back();
}

const char* kLines = "L1=LINE/0,0,0,10\nL2=LINE/0,5,10,5\nCUTTER/2\nFROM/-5,-5,0\n";

TEST(AptContour, StartupAgainstOneLineToOnPast) {
  for (const auto& [mod, x] : {std::pair{"TO", -1.0}, {"ON", 0.0}, {"PAST", 1.0}}) {
    const AptRun r = run(std::string(kLines) + "GO/" + mod + ",L1\nFINI\n");
    EXPECT_EQ(r.diags.error_count(), 0) << mod;
    expect_at(end_of(r, 5), x, -5, 0);
  }
}

TEST(AptContour, StartupAgainstACircle) {
  const AptRun to = run("C=CIRCLE/10,0,2\nCUTTER/1\nFROM/0,0,0\nGO/TO,C\nFINI\n");
  expect_at(end_of(to, 4), 7.5, 0, 0);
  const AptRun past = run("C=CIRCLE/10,0,2\nCUTTER/1\nFROM/0,0,0\nGO/PAST,C\nFINI\n");
  expect_at(end_of(past, 4), 8.5, 0, 0);
}

TEST(AptContour, StartupAgainstThreeSurfacesTakesThePartSurfacesZ) {
  const std::string geo =
      "L1=LINE/50,50,50,-20\nL4=LINE/0,50,10,50\nPL=PLANE/0,0,1,-16\nCUTTER/20\nFROM/70,70,0\n";
  expect_at(end_of(run(geo + "GO/TO,L1,TO,PL,TO,L4\nFINI\n"), 6), 60, 60, -16);
  expect_at(end_of(run(geo + "GO/PAST,L1,PL,PAST,L4\nFINI\n"), 6), 40, 40, -16);
  // The part surface stays: a later motion is at its z too.
  const AptRun r = run(geo + "GO/TO,L1,TO,PL,TO,L4\nTLLFT,GOLFT/L1,PAST,(LINE/0,0,10,0)\nFINI\n");
  EXPECT_EQ(r.diags.error_count(), 0);
  expect_at(end_of(r, 7), 60, -10, -16);
}

TEST(AptContour, AlongALineToOnPastACheckLine) {
  for (const auto& [mod, y] : {std::pair{"TO", 4.0}, {"ON", 5.0}, {"PAST", 6.0}}) {
    const AptRun r = run(std::string(kLines) + "GO/TO,L1\nTLLFT,GOLFT/L1," + mod + ",L2\nFINI\n");
    EXPECT_EQ(r.diags.error_count(), 0) << mod;
    expect_at(end_of(r, 6), -1, y, 0);
  }
}

TEST(AptContour, TheNthIntersectionCountsToAndPastInTurn) {
  // research/apt.md §5.1: a 0.5 radius tool along y = -0.5 into a circle of
  // radius 3 at (5,0): TO 1.536, PAST 2.551, TO 7.449, PAST 8.464.
  const std::string geo =
      "L0=LINE/0,0,10,0\nC=CIRCLE/5,0,3\nCUTTER/1\nFROM/-2,-0.5,0\nINDIRV/1,0,0\nTLRGT,GOFWD/L0,";
  const std::pair<const char*, double> cases[] = {{"C", 1.5358984},
                                                  {"PAST,C", 2.5505103},
                                                  {"2,INTOF,C", 7.4494897},
                                                  {"PAST,2,INTOF,C", 8.4641016},
                                                  {"ON,C", 2.0419601}};
  for (const auto& [tail, x] : cases) {
    const AptRun r = run(geo + tail + "\nFINI\n");
    EXPECT_EQ(r.diags.error_count(), 0) << tail;
    expect_at(end_of(r, 6), x, -0.5, 0);
  }
}

TEST(AptContour, ImplicitCheckSurfaceIsTheNextDriveSurface) {
  // GOLFT before GOLFT: TO the next drive surface; GOFWD before: TANTO.
  const AptRun to = run(std::string(kLines) +
                        "L3=LINE/-10,0,-10,10\nGO/TO,L1\nTLLFT,GOLFT/L1\nGOLFT/L2,PAST,L3\nFINI\n");
  EXPECT_EQ(to.diags.error_count(), 0);
  expect_at(end_of(to, 7), -1, 4, 0);
  expect_at(end_of(to, 8), -11, 4, 0);
  const AptRun tanto = run(std::string(kLines) +
                           "C=CIRCLE/-3,5,3\nGO/TO,L1\nTLLFT,GOLFT/L1\nGOFWD/C,PAST,L2\nFINI\n");
  EXPECT_EQ(tanto.diags.error_count(), 0);
  expect_at(end_of(tanto, 7), -1, 5, 0);
  expect_at(end_of(tanto, 8), -1.2679492, 6, 0);
  // The deferred statement's records keep its place: before the next one's.
  int last_isn = 0;
  for (const ClRecord& rec : tanto.result.records)
    if (rec.cls == cls::kSource) {
      EXPECT_GT(rec.sub, last_isn);
      last_isn = rec.sub;
    }
}

TEST(AptContour, CircleMotionWritesTheCircleThenItsPoints) {
  const AptRun r =
      run(std::string(kLines) +
          "C=CIRCLE/-3,5,3\nGO/TO,L1\nTLLFT,GOLFT/L1,TANTO,C\nGOFWD/C,PAST,L2\nFINI\n");
  EXPECT_EQ(r.diags.error_count(), 0);
  const ClRecord* circle = nullptr;
  for (const ClRecord& rec : r.result.records)
    if (rec.cls == cls::kSurface) circle = &rec;
  ASSERT_NE(circle, nullptr);
  EXPECT_EQ(circle->sub, 2);
  ASSERT_EQ(circle->words.size(), 12u);
  EXPECT_EQ(circle->words[3].text, "     C");
  EXPECT_DOUBLE_EQ(circle->words[5].real, -3.0);
  EXPECT_DOUBLE_EQ(circle->words[11].real, 3.0);
  // The tool inside the circle (concave): the points on the offset circle
  // of radius 2, the chords toward the centre by at most OUTTOL (.0005,
  // the default) and IBM's widening (.00005), never toward the part.
  const auto p = points_of(r, 8);
  ASSERT_GT(p.size(), 2u);
  for (std::size_t i = 0; i + 1 < p.size(); ++i) {
    const double mx = (p[i].x + p[i + 1].x) / 2 + 3, my = (p[i].y + p[i + 1].y) / 2 - 5;
    EXPECT_LE(std::hypot(p[i].x + 3, p[i].y - 5), 2.0 + 1e-9) << i;
    EXPECT_GE(std::hypot(mx, my), 2.0 - 0.00055 - 1e-9) << i;
  }
}

Path ccw_circle(core::Vec2 c, double rho) {
  Path p;
  p.circle = true;
  p.c = c;
  p.rho = rho;
  p.sense = 1;
  return p;
}

TEST(AptSegments, HalfStepsRoundedUpToEvenOnTheBandsOuterRadius) {
  // ρ = 2 counter-clockwise a quarter turn, OUTTOL .01: half step
  // acos(2/2.01) = 5.7154°, 90/5.7154 = 15.7 → 16 half steps, 8 points on
  // r = 2.01 at 5.625°, 16.875°, ...
  const Path p = ccw_circle({0, 0}, 2);
  std::string why;
  const auto pts = segment_arc(p, {2, 0}, {0, 2}, 0.0, 0.01, true, 0.0, 1000, why);
  ASSERT_TRUE(pts) << why;
  ASSERT_EQ(pts->size(), 8u);
  EXPECT_NEAR((*pts)[0].x, 2.0003213, 1e-7);
  EXPECT_NEAR((*pts)[0].y, 0.1970145, 1e-7);
  EXPECT_NEAR((*pts)[3].x, 1.5537510, 1e-7);
  EXPECT_NEAR((*pts)[7].y, 2.0003213, 1e-7);
}

TEST(AptSegments, ConcaveBandWidenedAsIbmDoes) {
  // Ex 10.1's C2: ρ 2.875 inside the circle, OUTTOL .005: IBM writes 14
  // points on ρ (the band 0.00505), not 15.
  const Path p = ccw_circle({14, 2}, 2.875);
  std::string why;
  const core::Vec2 te{14.125, 2 + std::sqrt(2.875 * 2.875 - 0.125 * 0.125)};
  const core::Vec2 end{14 - std::sqrt(2.875 * 2.875 - 0.125 * 0.125), 1.875};
  EXPECT_EQ(segment_arc(p, te, end, 0, 0.005, false, 0.00005, 1000, why)->size(), 14u);
  EXPECT_EQ(segment_arc(p, te, end, 0, 0.005, false, 0.0, 1000, why)->size(), 15u);
  const auto pts = segment_arc(p, te, end, 0, 0.005, false, 0.00005, 1000, why);
  EXPECT_NEAR((*pts)[0].x, 13.9548233, 1e-7);
  EXPECT_NEAR((*pts)[0].y, 4.8746450, 1e-7);
}

TEST(AptContourErrors, ImpossibleMotionsAreErrorsAtTheStatement) {
  const std::string start = std::string(kLines) + "GO/TO,L1\n";
  const std::pair<const char*, const char*> cases[] = {
      {"TLLFT,GOLFT/L1,TO,(LINE/5,0,5,10)", "never meets"},       // parallel check line
      {"TLRGT,GOLFT/L1,TO,L2", "to the left of the drive line"},  // the tool on the other side
      {"TLLFT,GOLFT/L1,TANTO,(CIRCLE/5,5,1)", "not tangent"},
      {"TLLFT,GOLFT/L1,3,INTOF,L2", "fewer times"},
      {"TLLFT,GOFWD/L1,TO,L2", "right angle"},  // fwd is +x, L1 runs along y
      {"TLLFT,GOLFT/(LINE/-1,0,5,0),TO,L2", "neither way turns"}};
  for (const auto& [motion, says] : cases) {
    const AptRun r = run(start + motion + "\nGOTO/0,0,0\nFINI\n");
    ASSERT_EQ(r.diags.error_count(), 1) << motion;
    EXPECT_EQ(r.diags.all()[0].code, core::Code::AptNoSolution) << motion;
    EXPECT_EQ(r.diags.all()[0].loc.line, 6u) << motion;
    EXPECT_NE(r.diags.all()[0].message.find(says), std::string::npos) << r.diags.all()[0].message;
    expect_at(end_of(r, 7), 0, 0, 0);  // processing goes on
  }
}

TEST(AptContourErrors, WhatCannotRunSaysWhy) {
  EXPECT_TRUE(run(std::string(kLines) + "GOFWD/L1,TO,L2\nFINI\n").has(core::Code::AptBadArgument));
  EXPECT_TRUE(run(std::string(kLines) + "GOUP/L1,L2\nFINI\n").has(core::Code::AptNotSupported));
  EXPECT_TRUE(run(std::string(kLines) + "GO/TO,L1,(PLANE/1,1,1,0)\nFINI\n")
                  .has(core::Code::AptNotSupported));
  EXPECT_TRUE(run(std::string(kLines) + "GO/TO,L1\nGOLFT/L1,TO,L2,L1\nFINI\n")
                  .has(core::Code::AptNotSupported));
  // Both tolerances 0: no chord fits a circle.
  const AptRun zero = run(std::string(kLines) +
                          "C=CIRCLE/-3,5,3\nINTOL/0\nOUTTOL/0\nGO/TO,L1\nTLLFT,GOLFT/L1,TANTO,C\n"
                          "GOFWD/C,PAST,L2\nFINI\n");
  EXPECT_TRUE(zero.has(core::Code::AptNoSolution));
  // A tolerance that would write millions of points.
  const AptRun fine =
      run("C=CIRCLE/0,0,1000\nCUTTER/2\nINTOL/1E-12\nOUTTOL/1E-12\nFROM/0,-2000,0\nGO/TO,C\n"
          "TLLFT,GOLFT/C,TO,(LINE/0,0,10,0)\nFINI\n");
  ASSERT_TRUE(fine.has(core::Code::AptNoSolution));
  bool said = false;
  for (const auto& d : fine.diags.all())
    said = said || d.message.find("raise OUTTOL") != std::string::npos;
  EXPECT_TRUE(said);
}

TEST(AptContourErrors, OverflowIsAnErrorNotAnInfinitePoint) {
  // PAST a circle of radius 1.5e308 from inside with a cutter of radius
  // 5e307: the offset radius overflows.
  const AptRun r = run("C=CIRCLE/0,0,1.5E308\nCUTTER/1E308\nFROM/1,0,0\nGO/PAST,C\nFINI\n");
  ASSERT_EQ(r.diags.error_count(), 1);
  EXPECT_EQ(r.diags.all()[0].code, core::Code::AptNoSolution);
  EXPECT_NE(r.diags.all()[0].message.find("overflow"), std::string::npos);
  EXPECT_TRUE(points_of(r, 4).empty());
}

TEST(AptContourErrors, AfterAFailedMotionTheStartIsUnknownUntilAGoto) {
  const AptRun r = run(std::string(kLines) +
                       "GO/TO,L1\nTLLFT,GOLFT/L1,TO,(LINE/5,0,5,10)\nGOLFT/L2,TO,L1\n"
                       "GOTO/-1,0,0\nGOFWD/L1,TO,L2\nFINI\n");
  ASSERT_EQ(r.diags.error_count(), 2);
  EXPECT_NE(r.diags.all()[1].message.find("start is unknown"), std::string::npos);
  expect_at(end_of(r, 9), -1, 4, 0);
}

}  // namespace
}  // namespace usina::apt::test

namespace usina::apt::test {
namespace {

TEST(AptContourErrors, AProgramsCirclesWriteAtMostAMillionPoints) {
  // Each quarter turn about a circle of radius 1000 within OUTTOL 4e-8
  // writes about 88,000 points: the twelfth passes the program's million.
  std::string text =
      "C=CIRCLE/0,0,1000\nLX=LINE/0,0,10,0\nLY=LINE/0,0,0,10\nCUTTER/2\nOUTTOL/4E-8\n";
  for (int i = 0; i < 12; ++i)
    text += "FROM/0,-2000,0\nGO/TO,C\nTLLFT,GOLFT/C,TO,LX\n";
  const AptRun r = run(text + "FINI\n");
  ASSERT_EQ(r.diags.error_count(), 1);
  EXPECT_EQ(r.diags.all()[0].loc.line, 6u + 3 * 11 + 2);
  EXPECT_NE(r.diags.all()[0].message.find("points a program may write"), std::string::npos)
      << r.diags.all()[0].message;
}

}  // namespace
}  // namespace usina::apt::test
