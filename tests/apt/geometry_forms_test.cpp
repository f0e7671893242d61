// A test per definition form; the values are those of research/apt.md §4
// (the IBM processor's output on its geometry fixtures) or worked by hand.
#include "apt_run.hpp"

namespace usina::apt::test {
namespace {

// The research fixtures' geometry (research/apt.md §4.1).
const std::string kBase =
    "P1=POINT/0,0\nP2=POINT/160,0\nP3=POINT/160,60\nP4=POINT/35,90\nP8=POINT/130,60\n"
    "L1=LINE/P1,P2\nL2=LINE/P2,P3\nC1=CIRCLE/CENTER,P8,RADIUS,30\nL3=LINE/P4,PARLEL,L1\n"
    "L4=LINE/P4,P1\nC2=CIRCLE/40,60,15\nPL1=PLANE/P1,P2,P4\nL16=LINE/0,50,10,50\n";

AptRun base(const std::string& more) {
  AptRun r = run(kBase + more + "\nFINI\n");
  EXPECT_FALSE(r.diags.has_errors()) << (r.diags.all().empty() ? "" : r.diags.all()[0].message);
  return r;
}

TEST(AptPoint, Coordinates) {
  expect_canon(base("X=POINT/1,2,3").def("X"), {1, 2, 3});
  expect_canon(base("ZSURF/4\nX=POINT/1,2").def("X"), {1, 2, 4});
}

TEST(AptPoint, IntersectionOfTwoLines) {
  expect_canon(base("X=POINT/INTOF,L2,L3").def("X"), {160, 90, 0});
}

TEST(AptPoint, LineAndCircleBySelector) {
  expect_canon(base("X=POINT/XLARGE,INTOF,L16,C1").def("X"), {158.284271, 50, 0});
  expect_canon(base("X=POINT/XSMALL,INTOF,L16,C1").def("X"), {101.715729, 50, 0});
}

TEST(AptPoint, TwoCirclesBySelector) {
  const std::string c = "C9=CIRCLE/CENTER,P2,RADIUS,70\n";
  expect_canon(base(c + "X=POINT/YLARGE,INTOF,C1,C9").def("X"), {158.291634, 69.979150, 0});
  expect_canon(base(c + "X=POINT/YSMALL,INTOF,C1,C9").def("X"), {105.041699, 43.354183, 0});
}

TEST(AptPoint, OnCircleAtAngle) {
  expect_canon(base("X=POINT/C1,ATANGL,45").def("X"), {151.213204, 81.213203, 0});
  expect_canon(base("X=POINT/C2,ATANGL,-90").def("X"), {40, 45, 0});
}

TEST(AptPoint, CentreAndPolar) {
  expect_canon(base("X=POINT/CENTER,C1").def("X"), {130, 60, 0});
  expect_canon(base("X=POINT/RTHETA,XYPLAN,10,30").def("X"), {8.660254, 5, 0});
  expect_canon(base("X=POINT/THETAR,XYPLAN,30,10").def("X"), {8.660254, 5, 0});
}

TEST(AptPoint, ThreePlanes) {
  // x = 1, y = 2, z = 3 by hand.
  expect_canon(base("X=POINT/INTOF,(PLANE/1,0,0,1),(PLANE/0,1,0,2),(PLANE/0,0,1,3)").def("X"),
               {1, 2, 3});
}

TEST(AptLine, TwoPointsAndCoordinates) {
  expect_canon(base("").def("L1"), {0, -1, 0, 0});
  expect_canon(base("").def("L2"), {1, 0, 0, 160});
  expect_canon(base("").def("L4"), {-.932005, .362446, 0, 0});
  expect_canon(base("X=LINE/4,5,10,20").def("X"), {.928477, -.371391, 0, 1.856953});
  expect_canon(base("X=LINE/4,0,0,4,8,0").def("X"), {1, 0, 0, 4}, true);
}

TEST(AptLine, TangentFromPoint) {
  expect_canon(base("X=LINE/P1,LEFT,TANTO,C2").def("X"), {.929235, -.369490, 0, 0});
  expect_canon(base("X=LINE/P1,RIGHT,TANTO,C2").def("X"), {-.698466, .715644, 0, 0});
}

TEST(AptLine, PointAndAngle) {
  expect_canon(base("X=LINE/P1,ATANGL,30").def("X"), {-.5, .866025, 0, 0});
  expect_canon(base("X=LINE/P3,ATANGL,30,L4").def("X"), {-.988363, -.152115, 0, -167.264936});
  // SLOPE 1 is 45 degrees.
  expect_canon(base("X=LINE/P1,SLOPE,1").def("X"), {-.707107, .707107, 0, 0});
}

TEST(AptLine, ParallelAndPerpendicular) {
  expect_canon(base("").def("L3"), {0, -1, 0, -90});
  expect_canon(base("X=LINE/P1,PERPTO,L4").def("X"), {-.362446, -.932005, 0, 0});
  expect_canon(base("X=LINE/PARLEL,L4,XLARGE,10").def("X"), {.932005, -.362446, 0, 10});
}

TEST(AptLine, AxesAndIntercepts) {
  expect_canon(base("X=LINE/XAXIS").def("X"), {0, 1, 0, 0});
  expect_canon(base("X=LINE/YAXIS").def("X"), {1, 0, 0, 0});
  expect_canon(base("X=LINE/SLOPE,0.5,INTERC,3").def("X"), {-.447214, .894427, 0, 2.683282});
  expect_canon(base("X=LINE/ATANGL,30,INTERC,XAXIS,5").def("X"), {-.5, .866025, 0, -2.5});
}

TEST(AptCircle, CentreAndRadius) {
  expect_canon(base("").def("C2"), {40, 60, 0, 0, 0, 1, 15});
  expect_canon(base("").def("C1"), {130, 60, 0, 0, 0, 1, 30});
  expect_canon(base("X=CIRCLE/12,10,0,2").def("X"), {12, 10, 0, 0, 0, 1, 2});
}

TEST(AptCircle, CentreAndTangentOrThroughPoint) {
  expect_canon(base("X=CIRCLE/CENTER,P4,TANTO,L1").def("X"), {35, 90, 0, 0, 0, 1, 90});
  expect_canon(base("X=CIRCLE/CENTER,P1,P4").def("X"), {0, 0, 0, 0, 0, 1, 96.566040});
  expect_canon(base("X=CIRCLE/CENTER,P4,LARGE,TANTO,C1").def("X"),
               {35, 90, 0, 0, 0, 1, 129.624294});
}

TEST(AptCircle, ThroughThreePoints) {
  expect_canon(base("X=CIRCLE/P1,P2,P4").def("X"), {80, 20.694444, 0, 0, 0, 1, 82.633286});
}

TEST(AptCircle, TangentToTwoLines) {
  expect_canon(base("X=CIRCLE/XSMALL,L2,YLARGE,L1,RADIUS,10").def("X"), {150, 10, 0, 0, 0, 1, 10});
  expect_canon(base("X=CIRCLE/XLARGE,L4,YLARGE,L1,RADIUS,10").def("X"),
               {14.618449, 10, 0, 0, 0, 1, 10});
}

TEST(AptCircle, TangentToLineThroughPoint) {
  expect_canon(base("X=CIRCLE/TANTO,L1,XSMALL,P4,RADIUS,50").def("X"), {5, 50, 0, 0, 0, 1, 50});
}

TEST(AptCircle, TangentToLineAndCircle) {
  expect_canon(base("X=CIRCLE/YSMALL,L3,XSMALL,OUT,C1,RADIUS,10").def("X"),
               {95.358984, 80, 0, 0, 0, 1, 10});
  expect_canon(base("X=CIRCLE/YLARGE,L16,XLARGE,IN,C1,RADIUS,10").def("X"),
               {150, 60, 0, 0, 0, 1, 10});
}

TEST(AptCircle, TangentToTwoCircles) {
  expect_canon(base("X=CIRCLE/YLARGE,OUT,C2,OUT,C1,RADIUS,40").def("X"),
               {74.583333, 102.766728, 0, 0, 0, 1, 40});
}

TEST(AptPlane, Forms) {
  expect_canon(base("X=PLANE/0,0,2,10").def("X"), {0, 0, 1, 5});
  expect_canon(base("").def("PL1"), {0, 0, 1, 0});
  expect_canon(base("X=PLANE/P4,PARLEL,PL1").def("X"), {0, 0, 1, 0});
  expect_canon(base("X=PLANE/PARLEL,PL1,ZSMALL,10").def("X"), {0, 0, -1, 10});
  expect_canon(base("X=PLANE/P2,PERPTO,(VECTOR/1,1,0)").def("X"),
               {.707107, .707107, 0, 113.137085});
}

TEST(AptVector, Forms) {
  expect_canon(base("X=VECTOR/1,2,3").def("X"), {1, 2, 3});
  expect_canon(base("X=VECTOR/P1,P3").def("X"), {160, 60, 0});
}

}  // namespace
}  // namespace usina::apt::test
