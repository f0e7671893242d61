// PATERN: a test per definition form and per GOTO/pattern modifier, the
// points worked by hand (docs/apt.md, "Patterns").
#include <cmath>

#include "apt/canon_out.hpp"
#include "apt_run.hpp"

namespace usina::apt::test {
namespace {

const double kR2 = std::sqrt(2.0);

const std::string kBase =
    "P0=POINT/0,0\nP1=POINT/1,1\nP10=POINT/10,0\nV2=VECTOR/2,0,0\nV34=VECTOR/3,4,0\n"
    "VX=VECTOR/1,0,0\nVY=VECTOR/0,1,0\nC=CIRCLE/10,0,2\nA=PATERN/LINEAR,P0,(POINT/2,0),2\n";

AptRun base(const std::string& more) {
  AptRun r = run(kBase + more + "\nFINI\n");
  EXPECT_FALSE(r.diags.has_errors()) << (r.diags.all().empty() ? "" : r.diags.all()[0].message);
  return r;
}

void expect_points(const Geom& g, const std::vector<core::Vec3>& want) {
  ASSERT_EQ(g.type, GeomType::Pattern);
  ASSERT_EQ(g.points.size(), want.size());
  for (std::size_t i = 0; i < want.size(); ++i) {
    EXPECT_NEAR(g.points[i].x, want[i].x, 1e-9) << "point " << i + 1;
    EXPECT_NEAR(g.points[i].y, want[i].y, 1e-9) << "point " << i + 1;
    EXPECT_NEAR(g.points[i].z, want[i].z, 1e-9) << "point " << i + 1;
  }
}

TEST(AptPatern, LinearPointToPoint) {
  // 3 points from (0,0) to (10,0): the ends and the middle.
  expect_points(base("X=PATERN/LINEAR,P0,P10,3").def("X"), {{0, 0, 0}, {5, 0, 0}, {10, 0, 0}});
}

TEST(AptPatern, LinearAlongVectorByCount) {
  // The vector is the step: (1,1), (3,1), (5,1).
  expect_points(base("X=PATERN/LINEAR,P1,V2,3").def("X"), {{1, 1, 0}, {3, 1, 0}, {5, 1, 0}});
}

TEST(AptPatern, LinearIncrementList) {
  // Along (3,4)/5: 5 then 10 more: (3,4), (9,12).
  expect_points(base("X=PATERN/LINEAR,P0,V34,INCR,5,10").def("X"),
                {{0, 0, 0}, {3, 4, 0}, {9, 12, 0}});
}

TEST(AptPatern, LinearIncrementsAt) {
  // 2 steps of 1 then 1 step of 5: x = 0, 1, 2, 7.
  expect_points(base("X=PATERN/LINEAR,P0,VX,INCR,2,AT,1,INCR,1,AT,5").def("X"),
                {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {7, 0, 0}});
}

TEST(AptPatern, ArcBetweenAngles) {
  // Circle (10,0) r 2, 0° to 90° counter-clockwise in 3: 0°, 45°, 90°.
  expect_points(base("X=PATERN/ARC,C,0,90,CCLW,3").def("X"),
                {{12, 0, 0}, {10 + kR2, kR2, 0}, {10, 2, 0}});
  // Clockwise from 0° to 90° is 270° the other way: 0°, -135°, -270°.
  expect_points(base("X=PATERN/ARC,C,0,90,CLW,3").def("X"),
                {{12, 0, 0}, {10 - kR2, -kR2, 0}, {10, 2, 0}});
}

TEST(AptPatern, ArcWholeCircle) {
  // From an angle to itself: around once, n points, the last not the first.
  expect_points(base("X=PATERN/ARC,C,0,360,CCLW,4").def("X"),
                {{12, 0, 0}, {10, 2, 0}, {8, 0, 0}, {10, -2, 0}});
}

TEST(AptPatern, ArcIncrements) {
  // From 90° clockwise by 90° twice: 90°, 0°, -90°.
  expect_points(base("X=PATERN/ARC,C,90,CLW,INCR,2,AT,90").def("X"),
                {{10, 2, 0}, {12, 0, 0}, {10, -2, 0}});
  expect_points(base("X=PATERN/ARC,C,0,CCLW,INCR,90,180").def("X"),
                {{12, 0, 0}, {10, 2, 0}, {10, -2, 0}});
}

TEST(AptPatern, Random) {
  expect_points(base("X=PATERN/RANDOM,P1,A,(POINT/7,8,9)").def("X"),
                {{1, 1, 0}, {0, 0, 0}, {2, 0, 0}, {7, 8, 9}});
}

// The APT360 manual's parallelogram pattern (§4.5.3): the first pattern is
// the first column; a column at each point of the second, the second,
// fourth ... columns in the reverse order. By hand, A = (0,0),(2,0).
TEST(AptPatern, ParlelByPattern) {
  // B from A's first point: columns at offsets (0,0), (0,3), (0,6).
  expect_points(base("B=PATERN/LINEAR,P0,(POINT/0,6),3\nX=PATERN/PARLEL,A,B").def("X"),
                {{0, 0, 0}, {2, 0, 0}, {2, 3, 0}, {0, 3, 0}, {0, 6, 0}, {2, 6, 0}});
  // B from A's last point (2,0): the same offsets.
  expect_points(base("B=PATERN/LINEAR,(POINT/2,0),(POINT/2,3),2\nX=PATERN/PARLEL,A,B").def("X"),
                {{0, 0, 0}, {2, 0, 0}, {2, 3, 0}, {0, 3, 0}});
  // B ending at A's first point: read from its end, so A is the first column.
  expect_points(base("B=PATERN/LINEAR,(POINT/0,-3),P0,2\nX=PATERN/PARLEL,A,B").def("X"),
                {{0, 0, 0}, {2, 0, 0}, {2, -3, 0}, {0, -3, 0}});
}

TEST(AptPatern, ParlelAlongVector) {
  expect_points(base("X=PATERN/PARLEL,A,VY,3").def("X"),
                {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}, {0, 2, 0}, {2, 2, 0}});
  expect_points(base("X=PATERN/PARLEL,A,(VECTOR/0,2,0),INCR,1,4").def("X"),
                {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}, {0, 5, 0}, {2, 5, 0}});
  // INCR,n,AT,d: n columns d apart besides the pattern (the manual's §4.5.3.3).
  expect_points(base("X=PATERN/PARLEL,A,VY,INCR,2,AT,1.5").def("X"),
                {{0, 0, 0}, {2, 0, 0}, {2, 1.5, 0}, {0, 1.5, 0}, {0, 3, 0}, {2, 3, 0}});
}

TEST(AptPatern, NthPoint) {
  expect_canon(base("X=POINT/(PATERN/LINEAR,P0,P10,3),2").def("X"), {5, 0, 0});
  expect_canon(base("Y=POINT/A,2").def("Y"), {2, 0, 0});
}

// Each error at its statement, the processing going on past it.
void expect_error(const std::string& stmt, core::Code code) {
  const AptRun r = run(kBase + stmt + "\nOK=POINT/1,2\nFINI\n");
  EXPECT_TRUE(r.has(code)) << stmt;
  expect_canon(r.def("OK"), {1, 2, 0});
}

TEST(AptPatern, DefinitionErrors) {
  using core::Code;
  expect_error("X=PATERN/LINEAR,P0,P10,1", Code::AptBadArgument);
  expect_error("X=PATERN/LINEAR,P1,V2,2.5", Code::AptBadArgument);
  expect_error("X=PATERN/LINEAR,P1,V2,200000", Code::AptBadArgument);
  expect_error("X=PATERN/LINEAR,P0,(VECTOR/0,0,0),INCR,1", Code::AptBadArgument);
  expect_error("X=PATERN/LINEAR,P0,VX,INCR,2,AT", Code::AptBadArgument);
  expect_error("X=PATERN/LINEAR,P0,VX,INCR,0.5,AT,1", Code::AptBadArgument);
  expect_error("X=PATERN/ARC,C,0,90,CCLW,1", Code::AptBadArgument);
  expect_error("X=PATERN/ARC,C,0,90,3", Code::AptUnknownForm);
  expect_error("X=PATERN/CENTER,P0,P10,3", Code::AptUnknownForm);
  expect_error("X=PATERN/RANDOM,P0,(LINE/0,0,1,1)", Code::AptUnknownForm);
  expect_error("X=PATERN/RANDOM", Code::AptUnknownForm);
  // 1,000 points copied 1,000 times: beyond the 100,000 a pattern holds.
  expect_error("B=PATERN/LINEAR,P0,VX,1000\nX=PATERN/PARLEL,B,VY,1000", Code::AptBadArgument);
  // PARLEL of two patterns with no common first or last point.
  expect_error("B=PATERN/LINEAR,(POINT/5,5),(POINT/5,8),2\nX=PATERN/PARLEL,A,B",
               Code::AptBadArgument);
  expect_error("X=POINT/A,3", Code::AptBadArgument);
  expect_error("X=POINT/A,0", Code::AptBadArgument);
}

TEST(AptPatern, AProgramsPatternsHoldAtMostAMillionPoints) {
  std::string p = "P=POINT/0,0\nV=VECTOR/1,0,0\n";
  for (int i = 0; i < 10; ++i)
    p += "A" + std::to_string(i) + "=PATERN/LINEAR,P,V,100000\n";
  const AptRun ten = run(p + "FINI\n");
  EXPECT_FALSE(ten.diags.has_errors());
  const AptRun more = run(p + "B=PATERN/LINEAR,P,V,1\nFINI\n");
  EXPECT_TRUE(more.has(core::Code::AptBadArgument));
  // Visits too: ten times the 100,000 points of A0, then one more.
  std::string v = "P=POINT/0,0\nV=VECTOR/1,0,0\nA=PATERN/LINEAR,P,V,100000\n";
  for (int i = 0; i < 10; ++i)
    v += "GOTO/A\n";
  EXPECT_FALSE(run(v + "FINI\n").diags.has_errors());
  EXPECT_TRUE(run(v + "GOTO/A,RETAIN,1\nFINI\n").has(core::Code::AptBadArgument));
}

// The points of the 5000 records of line 11, the GOTO after kBase's 9 lines
// and the pattern.
std::vector<core::Vec3> goto_points(const AptRun& r) {
  std::vector<core::Vec3> out;
  for (const ClRecord& c : r.result.records)
    if (c.cls == cls::kMotion && c.src.line == 11)
      for (std::size_t i = 2; i + 2 < c.words.size(); i += 3)
        out.push_back({c.words[i].real, c.words[i + 1].real, c.words[i + 2].real});
  return out;
}

AptRun go(const std::string& mods) {
  return base("X=PATERN/LINEAR,P0,VX,4\nGOTO/X" + mods);
}

void expect_xs(const std::vector<core::Vec3>& ps, const std::vector<double>& xs) {
  ASSERT_EQ(ps.size(), xs.size());
  for (std::size_t i = 0; i < xs.size(); ++i)
    EXPECT_DOUBLE_EQ(ps[i].x, xs[i]) << "point " << i + 1;
}

TEST(AptPatern, GotoVisitsEachPoint) {
  const AptRun r = go("");
  expect_xs(goto_points(r), {0, 1, 2, 3});
  // One GOTO record named by the pattern.
  const ClRecord& last = r.result.records[r.result.records.size() - 3];
  EXPECT_EQ(last.cls, cls::kMotion);
  EXPECT_EQ(last.sub, 5);
  EXPECT_EQ(last.words[0].text, "     X");
}

TEST(AptPatern, GotoModifiers) {
  expect_xs(goto_points(go(",INVERS")), {3, 2, 1, 0});
  expect_xs(goto_points(go(",OMIT,2,THRU,3")), {0, 3});
  expect_xs(goto_points(go(",RETAIN,1,4")), {0, 3});
  // The numbers follow the output order (INVERS: 1 is the last point); CONST
  // makes them the definition's (the APT360 manual, §4.6.2 and §4.6.6).
  expect_xs(goto_points(go(",INVERS,OMIT,1")), {2, 1, 0});
  expect_xs(goto_points(go(",OMIT,1,INVERS")), {2, 1, 0});
  expect_xs(goto_points(go(",INVERS,CONST,OMIT,1")), {3, 2, 1});
  expect_xs(goto_points(go(",CONST,OMIT,1")), {1, 2, 3});  // without INVERS, the same order
  // Point 3 over a rise of 5: up at point 2, across, down (a RAPID).
  const AptRun r = go(",AVOID,5,3");
  const std::vector<core::Vec3> ps = goto_points(r);
  expect_xs(ps, {0, 1, 1, 2, 2, 3});
  EXPECT_DOUBLE_EQ(ps[2].z, 5.0);
  EXPECT_DOUBLE_EQ(ps[3].z, 5.0);
  EXPECT_DOUBLE_EQ(ps[4].z, 0.0);
  int rapids = 0;
  for (const ClRecord& c : r.result.records)
    rapids += c.cls == cls::kPost && c.sub == 5 ? 1 : 0;
  EXPECT_EQ(rapids, 1);
}

// The manual's example (§4.6.6, a pattern of 12 points):
// GOTO/PAT1,INVERS,RETAIN,2,THRU,4,6,8 and GOTO/PAT1,INVERS,CONST,RETAIN,11,THRU,9,7,5
// both go to points 11, 10, 9, 7, 5 (x = 10, 9, 8, 6, 4).
TEST(AptPatern, ConstNumbersByTheDefinition) {
  const std::string twelve = "X=PATERN/LINEAR,P0,VX,12\nGOTO/X";
  expect_xs(goto_points(base(twelve + ",INVERS,RETAIN,2,THRU,4,6,8")), {10, 9, 8, 6, 4});
  expect_xs(goto_points(base(twelve + ",INVERS,CONST,RETAIN,11,THRU,9,7,5")), {10, 9, 8, 6, 4});
  // AVOID's numbers too: the output's 1 under INVERS is the definition's 12.
  const std::vector<core::Vec3> ps = goto_points(base(twelve + ",INVERS,RETAIN,1,2,AVOID,4,2"));
  ASSERT_EQ(ps.size(), 4u);  // 12; up, across, 11
  EXPECT_DOUBLE_EQ(ps[1].z, 4.0);
  EXPECT_DOUBLE_EQ(ps[3].x, 10.0);
  const std::vector<core::Vec3> c =
      goto_points(base(twelve + ",INVERS,CONST,RETAIN,12,11,AVOID,4,11"));
  ASSERT_EQ(c.size(), 4u);
  EXPECT_DOUBLE_EQ(c[2].z, 4.0);
}

TEST(AptPatern, OverlappingListsAndSeveralAvoids) {
  // Ranges that overlap name each point once; two RETAINs keep what both name.
  expect_xs(goto_points(go(",RETAIN,1,THRU,3,2,THRU,4")), {0, 1, 2, 3});
  expect_xs(goto_points(go(",RETAIN,1,THRU,3,RETAIN,2,THRU,4")), {1, 2});
  expect_xs(goto_points(go(",OMIT,1,OMIT,1,THRU,2,RETAIN,2,THRU,4")), {2, 3});
  // Point 3 named by two AVOIDs: the larger rise, 8.
  const std::vector<core::Vec3> ps = goto_points(go(",AVOID,5,3,AVOID,8,2,THRU,3"));
  ASSERT_EQ(ps.size(), 8u);  // 1; up, across, 2; up, across, 3; 4
  EXPECT_DOUBLE_EQ(ps[1].z, 8.0);
  EXPECT_DOUBLE_EQ(ps[5].z, 8.0);
}

TEST(AptPatern, GotoErrors) {
  using core::Code;
  const std::string x = "X=PATERN/LINEAR,P0,VX,4\n";
  expect_error(x + "GOTO/X,OMIT,1,THRU,4", Code::AptBadArgument);
  expect_error(x + "GOTO/X,OMIT,5", Code::AptBadArgument);
  expect_error(x + "GOTO/X,OMIT", Code::AptBadArgument);
  expect_error(x + "GOTO/X,OMIT,1,THRU", Code::AptBadArgument);
  expect_error(x + "GOTO/X,AVOID,0,1", Code::AptBadArgument);
  expect_error(x + "GOTO/X,CONST,OMIT,5", Code::AptBadArgument);
  expect_error(x + "GOTO/X,2", Code::AptBadArgument);  // a feed: FEDRAT of its own
  expect_error(x + "GOTO/X,INVERS,CLW", Code::AptBadArgument);
  expect_error(x + "FROM/X", Code::AptBadArgument);
}

class Holes final : public canon::Sink {
 public:
  void on(const canon::Op& op) override {
    if (const auto* h = std::get_if<canon::Hole>(&op.kind)) at.push_back(h->at);
  }

  std::vector<canon::Vec3> at;
};

TEST(AptPatern, DrillsEachPointUnderACycle) {
  // The bolt circle of 4 holes: 0°, 90°, 180°, 270° on C.
  const AptRun r = base("X=PATERN/ARC,C,0,360,CCLW,4\nCYCLE/DRILL,3,IPM,50,1\nGOTO/X\nCYCLE/OFF");
  Holes h;
  to_canon(r.result.records, 1.0, h);
  ASSERT_EQ(h.at.size(), 4u);
  EXPECT_NEAR(h.at[1].x, 10.0, 1e-9);
  EXPECT_NEAR(h.at[1].y, 2.0, 1e-9);
  EXPECT_NEAR(h.at[3].y, -2.0, 1e-9);
}

}  // namespace
}  // namespace usina::apt::test
