// The seed's example program (tests/programs/romi/seed-000-example.nc) as
// spec/romi.md says it must come out: the programmed contour (cutter
// compensation left out, as a part drawing shows it), the pocket, the holes.
#include <fstream>
#include <sstream>

#include "romi_test_support.hpp"

namespace usina::gcode::romi_test {
namespace {

std::string seed_program() {
  std::ifstream in(std::string(USINA_TEST_DIR) + "/programs/romi/seed-000-example.nc");
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(RomiSeed, ContourAsTheSpecSays) {
  InterpOptions o;
  o.ignore_cutter_comp = true;
  auto r = run_romi(seed_program(), o);
  ASSERT_TRUE(r->ok) << r->first_error_text();
  std::vector<Vec3> contour;
  std::vector<canon::Arc> arcs;
  for (const canon::Op& op : r->path.ops()) {
    if (op.origin != canon::Origin::Program) continue;
    if (const auto* f = std::get_if<canon::Feed>(&op.kind)) contour.push_back(f->to);
    if (const auto* a = std::get_if<canon::Arc>(&op.kind)) {
      contour.push_back(a->to);
      arcs.push_back(*a);
    }
  }
  const double want[][2] = {{200, 300},         {270.711, 370.711}, {770.711, 370.711},
                            {840.711, 300.711}, {840.711, 50.711},  {400.711, 50.711},
                            {240.689, 50.689},  {200, 150}};
  ASSERT_EQ(contour.size(), 8u);
  for (std::size_t i = 0; i < 8; ++i)
    expect_near(contour[i], {want[i][0], want[i][1], 0}, 1e-3);
  ASSERT_EQ(arcs.size(), 2u);
  expect_near(arcs[0].center, {770.711, 300.711, 0}, 1e-3);  // the R70 corner, clockwise
  EXPECT_EQ(arcs[0].turn, -1);
  expect_near(arcs[1].center, {320.7, 50.7, 0}, 1e-9);  // the semicircle, counter-clockwise
  EXPECT_EQ(arcs[1].turn, 1);
  const auto pocket = r->all<canon::Pocket>();
  ASSERT_EQ(pocket.size(), 1u);
  EXPECT_EQ(pocket[0].outline.start.x, 400.0);
  EXPECT_EQ(pocket[0].outline.start.y, 260.0);
  const auto holes = r->all<canon::Hole>();
  ASSERT_EQ(holes.size(), 12u);
  for (const canon::Hole& h : holes) {
    EXPECT_EQ(h.diameter, 20.0);
    EXPECT_EQ(h.depth, 40.0);
  }
}

}  // namespace
}  // namespace usina::gcode::romi_test
