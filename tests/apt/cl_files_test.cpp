// The real CL files of tests/programs/apt/cl (their provenance in that
// folder's README): each read without an error, its arcs counted, and drawn.
#include <fstream>
#include <sstream>

#include "apt/canon_out.hpp"
#include "apt/cl_text.hpp"
#include "apt_run.hpp"
#include "support/files.hpp"
#include "support/usina_process.hpp"

namespace usina::apt::test {
namespace {

using usina::test::quote;

std::string fixture(const std::string& name) {
  return std::string(USINA_TEST_DIR) + "/programs/apt/cl/" + name;
}

struct Counted {
  int arcs = 0, feeds = 0, traverses = 0, holes = 0, tools = 0;
};

class Count final : public canon::Sink {
 public:
  void on(const canon::Op& op) override {
    c.arcs += std::holds_alternative<canon::Arc>(op.kind) ? 1 : 0;
    c.feeds += std::holds_alternative<canon::Feed>(op.kind) ? 1 : 0;
    c.traverses += std::holds_alternative<canon::Traverse>(op.kind) ? 1 : 0;
    c.holes += std::holds_alternative<canon::Hole>(op.kind) ? 1 : 0;
    c.tools += std::holds_alternative<canon::ToolChange>(op.kind) ? 1 : 0;
  }

  Counted c;
};

Counted read_fixture(const std::string& name) {
  std::ifstream in(fixture(name), std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  core::DiagnosticList diags;
  Count count;
  to_canon(read_cl_text(s.str(), 0, ClDialect::AptCl, diags), 1.0, count);
  EXPECT_EQ(diags.all().size(), 0u) << name << ": " << diags.all()[0].message;
  return count.c;
}

TEST(AptClFiles, SolidWorksContourHasItsEightArcs) {
  const Counted c = read_fixture("lateral-leg-holder.apt");
  EXPECT_EQ(c.arcs, 8);
  EXPECT_EQ(c.tools, 1);
  EXPECT_EQ(c.holes, 0);
}

TEST(AptClFiles, SolidWorksDrillingHasItsHoles) {
  const Counted c = read_fixture("Guincho_Lbar.apt");
  EXPECT_EQ(c.arcs, 0);
  EXPECT_EQ(c.holes, 12);  // 4 spotted, 4 drilled, 4 drilled deeper
  EXPECT_EQ(c.tools, 2);
}

TEST(AptClFiles, SolidWorksMixedPartHasItsArcsAndHoles) {
  const Counted c = read_fixture("Dem-target2.apt");
  EXPECT_EQ(c.arcs, 75);
  EXPECT_EQ(c.holes, 8);
  EXPECT_EQ(c.tools, 3);
}

TEST(AptClFiles, EachIsDrawnAndPosted) {
  const usina::test::TempDir dir;
  for (const char* name : {"lateral-leg-holder.apt", "Guincho_Lbar.apt", "Dem-target2.apt"}) {
    const std::string svg = dir.path(std::string(name) + ".svg");
    const auto d =
        usina::test::usina("draw --from aptcl " + quote(fixture(name)) + " -o " + quote(svg));
    EXPECT_EQ(d.status, 0) << name << d.err;
    EXPECT_NE(usina::test::slurp(svg).find("<line x1="), std::string::npos) << name;
    const auto nc =
        usina::test::usina("convert --from aptcl " + quote(fixture(name)) + " --post fanuc");
    EXPECT_EQ(nc.status, 0) << name << nc.err;
  }
}

}  // namespace
}  // namespace usina::apt::test
