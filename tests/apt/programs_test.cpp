// The programs of tests/programs/apt and their tool paths, checked by hand
// in that folder's README.
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

}  // namespace
}  // namespace usina::apt::test
