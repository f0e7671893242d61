// Every error form of the definitions: a diagnostic at the statement, and
// processing goes on.
#include "apt_run.hpp"

namespace usina::apt::test {
namespace {

const std::string kBase =
    "P1=POINT/0,0\nP2=POINT/160,0\nP8=POINT/130,60\nL1=LINE/P1,P2\n"
    "C1=CIRCLE/CENTER,P8,RADIUS,30\nL3=LINE/0,90,10,90\n";

TEST(AptGeometryErrors, ParallelLinesDoNotMeet) {
  const AptRun r = run(kBase + "X=POINT/INTOF,L1,L3\nFINI\n");
  ASSERT_TRUE(r.has(core::Code::AptNoSolution));
  EXPECT_EQ(r.diags.all()[0].loc.line, 7u);
}

TEST(AptGeometryErrors, LineMissesCircle) {
  EXPECT_TRUE(run(kBase + "X=POINT/XLARGE,INTOF,L1,C1\nFINI\n").has(core::Code::AptNoSolution));
}

TEST(AptGeometryErrors, CirclesApart) {
  EXPECT_TRUE(
      run(kBase + "X=POINT/XLARGE,INTOF,C1,(CIRCLE/0,0,5)\nFINI\n").has(core::Code::AptNoSolution));
}

TEST(AptGeometryErrors, CoincidentPointsMakeNoLine) {
  EXPECT_TRUE(run(kBase + "X=LINE/P1,P1\nFINI\n").has(core::Code::AptNoSolution));
}

TEST(AptGeometryErrors, CollinearPointsMakeNoCircle) {
  EXPECT_TRUE(run(kBase + "X=CIRCLE/P1,P2,(POINT/50,0)\nFINI\n").has(core::Code::AptNoSolution));
}

TEST(AptGeometryErrors, TangentFromInsideTheCircle) {
  EXPECT_TRUE(run(kBase + "X=LINE/P8,LEFT,TANTO,C1\nFINI\n").has(core::Code::AptNoSolution));
}

TEST(AptGeometryErrors, ZeroRadius) {
  EXPECT_TRUE(run(kBase + "X=CIRCLE/1,2,0\nFINI\n").has(core::Code::AptNoSolution));
}

TEST(AptGeometryErrors, SelectorAlongTheLine) {
  // L1 runs along X: it has no XLARGE side.
  EXPECT_TRUE(run(kBase + "X=LINE/PARLEL,L1,XLARGE,5\nFINI\n").has(core::Code::AptNoSolution));
}

TEST(AptGeometryErrors, UnknownFormIsIbmError1000) {
  const AptRun r = run(kBase + "X=CIRCLE/P1,LEFT\nFINI\n");
  ASSERT_TRUE(r.has(core::Code::AptUnknownForm));
  EXPECT_NE(r.diags.all()[0].message.find("POINT, LEFT"), std::string::npos);
}

TEST(AptGeometryErrors, FormNotBuiltSaysSo) {
  const AptRun r = run(kBase + "X=LINE/LEFT,TANTO,C1,RIGHT,TANTO,(CIRCLE/0,0,5)\nFINI\n");
  ASSERT_TRUE(r.has(core::Code::AptNotSupported));
  EXPECT_NE(r.diags.all()[0].message.find("does not compute"), std::string::npos);
}

TEST(AptGeometryErrors, EveryErrorOfARunIsReported) {
  const AptRun r =
      run(kBase + "X=LINE/P1,P1\nY=POINT/INTOF,L1,L3\nZ=POINT/1,2\nW=CIRCLE/Q,1\nFINI\n");
  EXPECT_EQ(r.diags.error_count(), 3);
  expect_canon(r.def("Z"), {1, 2, 0});  // the statements after the errors ran
}

}  // namespace
}  // namespace usina::apt::test
