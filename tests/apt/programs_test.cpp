// The programs of tests/programs/apt and their tool paths, checked by hand
// in that folder's README.
#include <cmath>
#include <fstream>
#include <sstream>

#include "apt/canon_out.hpp"
#include "apt_run.hpp"

namespace usina::apt::test {
namespace {

std::string program(const std::string& name) {
  std::ifstream in(std::string(USINA_TEST_DIR) + "/programs/apt/" + name);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

class Moves final : public canon::Sink {
 public:
  void on(const canon::Op& op) override {
    if (const auto* t = std::get_if<canon::Traverse>(&op.kind)) points.push_back({t->to, true});
    if (const auto* f = std::get_if<canon::Feed>(&op.kind)) points.push_back({f->to, false});
  }

  std::vector<std::pair<core::Vec3, bool>> points;  // the point, whether a traverse
};

TEST(AptPrograms, GrooverGeometry) {
  const AptRun r = run(program("groover_geometry.apt"));
  EXPECT_EQ(r.diags.all().size(), 0u);
  expect_canon(r.def("L1"), {0, -1, 0, 0});
  expect_canon(r.def("L2"), {1, 0, 0, 160});
  expect_canon(r.def("C1"), {130, 60, 0, 0, 0, 1, 30});
  expect_canon(r.def("L3"), {0, -1, 0, -90});
  expect_canon(r.def("L4"), {-.932005, .362446, 0, 0});
  expect_canon(r.def("PL1"), {0, 0, 1, 0});
}

TEST(AptPrograms, GrooverDrillingPath) {
  const AptRun r = run(program("groover_drill.apt"));
  EXPECT_EQ(r.diags.all().size(), 0u);
  Moves m;
  to_canon(r.result.records, 1.0, m);
  const std::vector<std::pair<core::Vec3, bool>> want = {
      {{-50, -50, 10}, true}, {{70, 30, 0}, false},    {{70, 30, -15}, false}, {{70, 30, 0}, false},
      {{120, 30, 0}, false},  {{120, 30, -15}, false}, {{120, 30, 0}, false},  {{70, 60, 0}, false},
      {{70, 60, -15}, false}, {{70, 60, 0}, false},    {{-50, -50, 10}, true}};
  ASSERT_EQ(m.points.size(), want.size());
  for (std::size_t i = 0; i < want.size(); ++i) {
    EXPECT_EQ(m.points[i].first, want[i].first) << "move " << i;
    EXPECT_EQ(m.points[i].second, want[i].second) << "move " << i;
  }
}

TEST(AptPrograms, GrooverContourPath) {
  const AptRun r = run(program("groover_contour.apt"));
  EXPECT_EQ(r.diags.all().size(), 0u);
  Moves m;
  to_canon(r.result.records, 1.0, m, Circles::Chords);
  // The corners worked by hand in the README (the arc's points between
  // (170,60) and (130,100) are checked by their distance to (130,60)).
  const std::vector<core::Vec3> corners = {
      {-50, -50, 0}, {-3.8888889, -10, 0}, {170, -10, 0},         {170, 60, 0},
      {130, 100, 0}, {28.1593289, 100, 0}, {-14.6184488, -10, 0}, {-50, -50, 0}};
  ASSERT_GT(m.points.size(), corners.size());
  std::size_t k = 0;
  for (const auto& [p, rapid] : m.points) {
    const bool corner = k < corners.size() && std::fabs(p.x - corners[k].x) < 1e-6 &&
                        std::fabs(p.y - corners[k].y) < 1e-6;
    if (corner) {
      ++k;
      continue;
    }
    // Between (170,60) and (130,100): on the arc about C1's centre, 40
    // from it within OUTTOL (.05), never nearer.
    EXPECT_EQ(k, 4u) << "a point off the contour: " << p.x << "," << p.y;
    const double d = std::hypot(p.x - 130, p.y - 60);
    EXPECT_GE(d, 40 - 1e-9);
    EXPECT_LE(d, 40.05 + 1e-9);
  }
  EXPECT_EQ(k, corners.size());
}

class Arcs final : public canon::Sink {
 public:
  void on(const canon::Op& op) override {
    if (const auto* a = std::get_if<canon::Arc>(&op.kind)) arcs.push_back(*a);
    if (std::holds_alternative<canon::Feed>(op.kind)) ++feeds;
  }

  std::vector<canon::Arc> arcs;
  int feeds = 0;
};

TEST(AptPrograms, GrooverContourCircleIsOneArc) {
  // GOFWD/C1,TANTO,L3 by hand (README): from (170,60) counter-clockwise
  // about C1's centre (130,60), radius 40, a quarter turn to (130,100).
  const AptRun r = run(program("groover_contour.apt"));
  Arcs a;
  to_canon(r.result.records, 1.0, a);
  ASSERT_EQ(a.arcs.size(), 1u);
  EXPECT_NEAR(a.arcs[0].to.x, 130, 1e-9);
  EXPECT_NEAR(a.arcs[0].to.y, 100, 1e-9);
  EXPECT_EQ(a.arcs[0].center, (canon::Vec3{130, 60, 0}));
  EXPECT_EQ(a.arcs[0].normal, (canon::Vec3{0, 0, 1}));
  EXPECT_EQ(a.arcs[0].turn, 1);
  EXPECT_EQ(a.feeds, 6);  // the straight sides: L1 start, L1, L2, L3, L4, back to P0
}

}  // namespace
}  // namespace usina::apt::test

namespace usina::apt::test {
namespace {

class Drilled final : public canon::Sink {
 public:
  void on(const canon::Op& op) override {
    if (const auto* h = std::get_if<canon::Hole>(&op.kind)) holes.push_back(h->at);
    if (const auto* t = std::get_if<canon::Traverse>(&op.kind)) traverses.push_back(t->to);
  }

  std::vector<canon::Vec3> holes;
  std::vector<canon::Vec3> traverses;
};

void expect_xyz(const canon::Vec3& p, const canon::Vec3& want, const std::string& what) {
  EXPECT_NEAR(p.x, want.x, 1e-9) << what;
  EXPECT_NEAR(p.y, want.y, 1e-9) << what;
  EXPECT_NEAR(p.z, want.z, 1e-9) << what;
}

TEST(AptPrograms, BoltCircleDrilledByGotoPattern) {
  // README.md: 6 holes on r 40 about (50,40) at 30°, 90° ... 330°; 40 sin 60°
  // = 34.6410162, 40 cos 60° = 20.
  const AptRun r = run(program("bolt_circle.apt"));
  EXPECT_EQ(r.diags.all().size(), 0u);
  const double s = 20.0 * std::sqrt(3.0);
  const std::vector<canon::Vec3> want = {{50 + s, 60, 0}, {50, 80, 0}, {50 - s, 60, 0},
                                         {50 - s, 20, 0}, {50, 0, 0},  {50 + s, 20, 0}};
  const Geom bolt = r.def("BOLT");
  ASSERT_EQ(bolt.points.size(), 6u);
  for (std::size_t i = 0; i < 6; ++i)
    expect_xyz(bolt.points[i], want[i], "point " + std::to_string(i + 1));
  expect_canon(r.def("H4"), {50 - s, 20, 0});
  Drilled d;
  to_canon(r.result.records, 1.0, d);
  ASSERT_EQ(d.holes.size(), 6u);
  for (std::size_t i = 0; i < 6; ++i)
    expect_xyz(d.holes[i], want[i], "hole " + std::to_string(i + 1));
  // FROM, then per hole a traverse to 3 above it and one back up; before
  // the 4th, up to 20 over the 3rd and across at 20 (AVOID), then down to 3.
  ASSERT_EQ(d.traverses.size(), 1u + 12u + 2u + 1u);
  expect_xyz(d.traverses[7], {50 - s, 60, 20}, "AVOID: up");
  expect_xyz(d.traverses[8], {50 - s, 20, 20}, "AVOID: across");
  expect_xyz(d.traverses[9], {50 - s, 20, 3}, "the 4th hole's clearance");
}

}  // namespace
}  // namespace usina::apt::test
