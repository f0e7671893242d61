// Speeds and feeds from the cited tables (data/materials.toml) against
// values computed by hand: n = vc·1000/(π·D), vf = fz·z·n (fn·n for a drill).
#include <gtest/gtest.h>

#include "job/materials.hpp"
#include "job_test_util.hpp"
#include "support/files.hpp"

namespace usina::job {
namespace {

std::vector<Material> shipped() {
  core::DiagnosticList d;
  const std::string text = test::slurp(testing::repo("data/materials.toml"));
  auto ms = read_materials(text, 0, d);
  EXPECT_TRUE(ms) << (d.all().empty() ? "" : d.all()[0].message);
  return ms.value_or(std::vector<Material>{});
}

Tool tool(ToolType type, double d, int z, ToolMaterial m) {
  Tool t;
  t.number = 1;
  t.type = type;
  t.diameter = d;
  t.flutes = z;
  t.cutting_length = 20;
  t.material = m;
  return t;
}

const CuttingRow& row(const std::vector<Material>& ms, const char* name, const Tool& t,
                      CutKind cut) {
  const Material* m = find_material(ms, name);
  EXPECT_NE(m, nullptr) << name;
  const CuttingRow* r = cutting_row(*m, t, cut);
  EXPECT_NE(r, nullptr) << name;
  return *r;
}

TEST(Cutting, EveryShippedRowNamesItsSource) {
  const auto ms = shipped();
  ASSERT_GE(ms.size(), 6u);
  for (const Material& m : ms) {
    for (const CuttingRow& r : m.rows)
      EXPECT_NE(r.source.find('['), std::string::npos) << m.name;
  }
}

// 6 mm 3-flute carbide in wrought aluminium: 800 SFM = 243.84 m/min, the
// 3/16" column's .002 in = 0.0508 mm per tooth (a 6 mm tool is below 1/4").
TEST(Cutting, EndMillInAluminiumByHand) {
  const auto ms = shipped();
  const Tool t = tool(ToolType::Flat, 6, 3, ToolMaterial::Carbide);
  const auto c = cutting_conditions(row(ms, "aluminium-wrought", t, CutKind::Mill), t, false, {});
  ASSERT_TRUE(c);
  EXPECT_NEAR(c->rpm, 12936.11, 0.01);
  EXPECT_NEAR(c->feed, 1971.46, 0.01);
  EXPECT_NEAR(c->plunge_feed, 1971.46 / 2, 0.01);
  EXPECT_FALSE(c->limited);
}

// The machine's 10000 rev/min caps n; the chip load stays, so vf drops:
// 0.0508 × 3 × 10000 = 1524.
TEST(Cutting, TheSpindlesLimitKeepsTheChipLoad) {
  const auto ms = shipped();
  const Tool t = tool(ToolType::Flat, 6, 3, ToolMaterial::Carbide);
  const auto c =
      cutting_conditions(row(ms, "aluminium-wrought", t, CutKind::Mill), t, false, {10000, 10000});
  ASSERT_TRUE(c);
  EXPECT_DOUBLE_EQ(c->rpm, 10000);
  EXPECT_NEAR(c->feed, 1524, 1e-9);
  EXPECT_TRUE(c->limited);
}

TEST(Cutting, TheAxesLimitCapsTheFeed) {
  const auto ms = shipped();
  const Tool t = tool(ToolType::Flat, 6, 3, ToolMaterial::Carbide);
  const auto c =
      cutting_conditions(row(ms, "aluminium-wrought", t, CutKind::Mill), t, false, {0, 1000});
  ASSERT_TRUE(c);
  EXPECT_NEAR(c->rpm, 12936.11, 0.01);
  EXPECT_DOUBLE_EQ(c->feed, 1000);
}

// Slotting: vc less 20 %, 195.072 m/min; D10 takes the 3/8" column, .003 in.
TEST(Cutting, SlottingTakesTwentyPercentOffTheSpeed) {
  const auto ms = shipped();
  const Tool t = tool(ToolType::Flat, 10, 3, ToolMaterial::Carbide);
  const auto c = cutting_conditions(row(ms, "aluminium-wrought", t, CutKind::Mill), t, true, {});
  ASSERT_TRUE(c);
  EXPECT_NEAR(c->rpm, 6209.33, 0.01);
  EXPECT_NEAR(c->feed, 1419.45, 0.01);
}

// A 6.8 mm HSS drill in aluminium: 200 SFPM = 60.96 m/min, 1/4"-1/2" feed
// .004 in/rev = 0.1016 mm; it feeds along Z at vf.
TEST(Cutting, DrillFeedIsPerRevolution) {
  const auto ms = shipped();
  const Tool t = tool(ToolType::Drill, 6.8, 2, ToolMaterial::Hss);
  const auto c = cutting_conditions(row(ms, "aluminium-wrought", t, CutKind::Drill), t, false, {});
  ASSERT_TRUE(c);
  EXPECT_NEAR(c->rpm, 2853.55, 0.01);
  EXPECT_NEAR(c->feed, 289.92, 0.01);
  EXPECT_DOUBLE_EQ(c->plunge_feed, c->feed);
}

TEST(Cutting, BeyondTheTablesEndThereIsNoData) {
  const auto ms = shipped();
  const Tool t = tool(ToolType::Drill, 20, 2, ToolMaterial::Hss);  // above 5/8"
  EXPECT_FALSE(cutting_conditions(row(ms, "aluminium-wrought", t, CutKind::Drill), t, false, {}));
}

TEST(Cutting, ACoatedToolTakesTheCarbideRow) {
  const auto ms = shipped();
  const Tool t = tool(ToolType::Flat, 6, 3, ToolMaterial::Coated);
  const Material* m = find_material(ms, "aluminium-wrought");
  ASSERT_NE(m, nullptr);
  const CuttingRow* r = cutting_row(*m, t, CutKind::Mill);
  ASSERT_NE(r, nullptr);
  EXPECT_EQ(r->tool_material, "carbide");
}

TEST(Cutting, TheWhySaysTheFormulaAndTheSource) {
  const auto ms = shipped();
  const Tool t = tool(ToolType::Flat, 6, 3, ToolMaterial::Carbide);
  const auto c =
      cutting_conditions(row(ms, "aluminium-wrought", t, CutKind::Mill), t, false, {10000, 0});
  ASSERT_TRUE(c);
  ASSERT_GE(c->why.size(), 3u);
  EXPECT_NE(c->why[0].find("243.84"), std::string::npos) << c->why[0];
  EXPECT_NE(c->why[1].find("max_rpm 10000"), std::string::npos) << c->why[1];
  EXPECT_NE(c->why.back().find("Torbide"), std::string::npos) << c->why.back();
}

TEST(Cutting, ARowWithoutItsSourceIsAnError) {
  core::DiagnosticList d;
  const auto ms = read_materials(
      "[[material]]\nname = \"x\"\n[[material.cutting]]\ntool = \"hss\"\ncut = \"mill\"\n"
      "vc = 20.0\nfz = [[3.0, 0.02]]\n",
      0, d);
  EXPECT_FALSE(ms);
  ASSERT_EQ(d.error_count(), 1);
  EXPECT_EQ(d.all()[0].code, core::Code::BadMaterials);
  EXPECT_EQ(d.all()[0].loc.line, 3u);
}

}  // namespace
}  // namespace usina::job
