// Chamfering along a contour (issue 16; docs/job.md, "Chamfering"): the
// tip's depth and the path's offset for a V tool of either angle with and
// without a flat tip, the edge's width measured back from the program's
// moves, the tool's choice, the library's angle and tip, every bad key.
#include <algorithm>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "../post/round_trip.hpp"
#include "canon/toolpath.hpp"
#include "job/make.hpp"
#include "job/tools.hpp"
#include "job_test_util.hpp"

namespace usina::job {
namespace {

using testing::find;
using testing::job_text;
using testing::load_text;

using testing::kFirstOpLine;

double tan_deg(double deg) {
  return std::tan(deg * std::numbers::pi / 180);
}

Tool cone(double diameter, double angle, double tip, double cutting_length = 20) {
  Tool t;
  t.type = ToolType::Chamfer;
  t.diameter = diameter;
  t.angle = angle;
  t.tip_diameter = tip;
  t.cutting_length = cutting_length;
  return t;
}

// By hand: z = w/tan(a) + tip offset, d = rt + tip offset * tan(a).
TEST(ChamferCut, NinetyDegreesPointed) {
  const ChamferCut c = chamfer_cut(cone(10, 90, 0), 1.0, 0.5);
  EXPECT_NEAR(c.depth, 1.5, 1e-12);
  EXPECT_NEAR(c.offset, 0.5, 1e-12);
}

TEST(ChamferCut, NinetyDegreesWithATipFlat) {
  const ChamferCut c = chamfer_cut(cone(10, 90, 1.0), 1.0, 0.5);
  EXPECT_NEAR(c.depth, 1.5, 1e-12);
  EXPECT_NEAR(c.offset, 1.0, 1e-12);  // 0.5 of tip radius and 0.5 * tan 45
}

TEST(ChamferCut, SixtyDegreesPointedAndWithATipFlat) {
  // a = 30 deg, tan a = 0.57735: z = 1/0.57735 + 0.5 = 2.23205.
  const ChamferCut pointed = chamfer_cut(cone(10, 60, 0), 1.0, 0.5);
  EXPECT_NEAR(pointed.depth, 2.2320508, 1e-6);
  EXPECT_NEAR(pointed.offset, 0.2886751, 1e-6);
  const ChamferCut flat = chamfer_cut(cone(10, 60, 1.0), 1.0, 0.5);
  EXPECT_NEAR(flat.depth, 2.2320508, 1e-6);
  EXPECT_NEAR(flat.offset, 0.7886751, 1e-6);
}

TEST(ChamferCut, ATipOffsetOfZeroPutsAPointedTipOnTheEdge) {
  const ChamferCut c = chamfer_cut(cone(10, 90, 0), 2.0, 0.0);
  EXPECT_NEAR(c.depth, 2.0, 1e-12);
  EXPECT_NEAR(c.offset, 0.0, 1e-12);
}

TEST(ChamferReach, TheEdgeFromTheTipToTheDiameterLessTheTipOffset) {
  // The shop's T12: D10 90 deg pointed, 5 mm of cone: 5 - 0.5 * tan 45.
  EXPECT_NEAR(chamfer_reach(cone(10, 90, 0, 5), 0.5), 4.5, 1e-12);
  // A flat of D2 takes its radius off the edge.
  EXPECT_NEAR(chamfer_reach(cone(10, 90, 2, 5), 0.5), 3.5, 1e-12);
  // A cutting length shorter than the cone ends the edge first.
  EXPECT_NEAR(chamfer_reach(cone(10, 90, 0, 2), 0.5), 1.5, 1e-12);
}

TEST(ChamferMill, TheSmallestWhoseEdgeReachesTheWidth) {
  std::vector<Tool> tools{cone(10, 90, 0), cone(6, 90, 0), cone(16, 90, 0)};
  tools[0].number = 12;
  tools[1].number = 13;
  tools[2].number = 14;
  EXPECT_EQ(chamfer_mill(tools, 1.0, 0.5).tool, &tools[1]);  // D6 reaches 2.5
  EXPECT_EQ(chamfer_mill(tools, 3.0, 0.5).tool, &tools[0]);  // D10 reaches 4.5
  const ToolChoice none = chamfer_mill(tools, 8.0, 0.5);
  EXPECT_EQ(none.tool, nullptr);
  EXPECT_NE(none.why.find("T14"), std::string::npos) << none.why;  // the widest, 7.5
  EXPECT_EQ(chamfer_mill({}, 1.0, 0.5).why, "the library has no chamfer mill");
}

// ---- the library's angle and tip ----

std::optional<std::vector<Tool>> library(const std::string& entry, core::DiagnosticList& diags) {
  return read_tool_library(
      "[[tool]]\nnumber = 12\ndiameter = 10.0\ncutting_length = 5.0\n"
      "material = \"carbide\"\n" +
          entry,
      0, diags);
}

TEST(ChamferLibrary, TheShopsChamferMillHasItsAngle) {
  core::DiagnosticList diags;
  const auto tools = library("type = \"chamfer\"\nangle = 90\ntip_diameter = 0.2\n", diags);
  ASSERT_TRUE(tools) << (diags.all().empty() ? "" : diags.all()[0].message);
  EXPECT_EQ((*tools)[0].angle, 90);
  EXPECT_EQ((*tools)[0].tip_diameter, 0.2);
}

TEST(ChamferLibrary, AChamferMillWithoutItsAngleIsAnError) {
  core::DiagnosticList diags;
  EXPECT_FALSE(library("type = \"chamfer\"\n", diags));
  const core::Diagnostic* d = find(diags, core::Code::BadToolLibrary);
  ASSERT_NE(d, nullptr);
  EXPECT_NE(d->message.find("included angle"), std::string::npos) << d->message;
}

TEST(ChamferLibrary, AnAngleOfNoConeIsAnError) {
  for (const char* angle : {"0", "180", "-30"}) {
    SCOPED_TRACE(angle);
    core::DiagnosticList diags;
    EXPECT_FALSE(library(std::string("type = \"chamfer\"\nangle = ") + angle + "\n", diags));
    const core::Diagnostic* d = find(diags, core::Code::BadToolLibrary);
    ASSERT_NE(d, nullptr);
    EXPECT_EQ(d->loc.line, 7u);
  }
}

TEST(ChamferLibrary, ATipAsWideAsTheToolIsAnError) {
  core::DiagnosticList diags;
  EXPECT_FALSE(library("type = \"chamfer\"\nangle = 90\ntip_diameter = 10\n", diags));
  const core::Diagnostic* d = find(diags, core::Code::BadToolLibrary);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->loc.line, 8u);
  EXPECT_NE(d->message.find("not below the diameter"), std::string::npos) << d->message;
}

TEST(ChamferLibrary, OnlyAConeHasAnAngleOrATip) {
  core::DiagnosticList diags;
  EXPECT_FALSE(library("type = \"flat\"\nangle = 90\n", diags));
  ASSERT_NE(find(diags, core::Code::BadToolLibrary), nullptr);
  core::DiagnosticList engraver;
  EXPECT_TRUE(library("type = \"engraver\"\nangle = 60\ntip_diameter = 0.1\n", engraver));
}

// ---- the job ----

const std::string kOutline =
    "[[operation]]\n"        // 10
    "type = \"chamfer\"\n"   // 11
    "layer = \"OUTLINE\"\n"  // 12
    "side = \"outside\"\n"   // 13
    "width = 1.0\n"          // 14
    "tool = 12\n"            // 15
    "rpm = 8000\n"           // 16
    "feed = 600\n";          // 17

std::string with(std::string text, const std::string& from, const std::string& to) {
  text.replace(text.find(from), from.size(), to);
  return text;
}

struct Made {
  std::unique_ptr<testing::Loaded> loaded;
  core::DiagnosticList diags;
  canon::Toolpath tp;
  bool ok = false;
};

Made make(const std::string& text) {
  Made m;
  m.loaded = load_text(text);
  EXPECT_TRUE(m.loaded->job) << (m.loaded->diags.all().empty() ? m.loaded->io_error
                                                               : m.loaded->diags.all()[0].message);
  if (m.loaded->job) m.ok = make_job(*m.loaded->job, m.tp, m.diags);
  return m;
}

// A library of the shop's T12 and the chamfer mills given, beside the job.
std::string job_with_tools(const test::TempDir& dir, const std::string& tools,
                           const std::string& ops) {
  const std::string path = dir.write("tools.toml", tools);
  return with(job_text(ops), testing::repo("examples/tools/shop.toml"), path);
}

// The cutting feeds' depths, and how far the path runs outside the
// outline's left edge (X0, straight from Y8 to Y72): the offset.
struct Measured {
  std::vector<double> depths;
  double offset = 0;
};

Measured measure(const canon::Toolpath& tp) {
  Measured m;
  double lowest_x = 1e300;
  for (const canon::Op& op : tp.ops()) {
    const auto* f = std::get_if<canon::Feed>(&op.kind);
    if (f == nullptr || f->to.z >= 0) continue;
    if (std::find(m.depths.begin(), m.depths.end(), f->to.z) == m.depths.end())
      m.depths.push_back(f->to.z);
    if (f->to.y > 8 - 1e-6 && f->to.y < 72 + 1e-6) lowest_x = std::min(lowest_x, f->to.x);
  }
  m.offset = -lowest_x;
  return m;
}

// The chamfer's width on the top face, from the moves: the cone's radius at
// Z0 (rt + |z| tan a) less the centre's distance from the edge.
double edge_width(const Measured& m, double angle, double tip) {
  return tip / 2 + -m.depths.front() * tan_deg(angle / 2) - m.offset;
}

TEST(Chamfer, TheShopsNinetyDegreeMillOutsideTheOutline) {
  const Made m = make(job_text(kOutline));
  ASSERT_TRUE(m.ok) << (m.diags.all().empty() ? "" : m.diags.all()[0].message);
  const Measured got = measure(m.tp);
  ASSERT_EQ(got.depths.size(), 1u);  // one pass
  EXPECT_NEAR(got.depths[0], -1.5, 1e-9);
  EXPECT_NEAR(got.offset, 0.5, 1e-3);
  EXPECT_NEAR(edge_width(got, 90, 0), 1.0, 1e-3);
}

TEST(Chamfer, ATipOffsetMovesTheTipDownAndThePathOut) {
  const Made m = make(with(job_text(kOutline), "width = 1.0\n", "width = 2.0\ntip_offset = 1.0\n"));
  ASSERT_TRUE(m.ok) << (m.diags.all().empty() ? "" : m.diags.all()[0].message);
  const Measured got = measure(m.tp);
  EXPECT_NEAR(got.depths[0], -3.0, 1e-9);
  EXPECT_NEAR(got.offset, 1.0, 1e-3);
  EXPECT_NEAR(edge_width(got, 90, 0), 2.0, 1e-3);
}

const std::string kSixty =
    "[[tool]]\nnumber = 21\nname = \"60 degree, tip D0.6\"\ntype = \"chamfer\"\n"
    "diameter = 12.0\nangle = 60.0\ntip_diameter = 0.6\ncutting_length = 10.0\n"
    "material = \"carbide\"\n"
    "[[tool]]\nnumber = 22\nname = \"90 degree, tip D1\"\ntype = \"chamfer\"\n"
    "diameter = 8.0\nangle = 90.0\ntip_diameter = 1.0\ncutting_length = 4.0\n"
    "material = \"carbide\"\n";

TEST(Chamfer, SixtyDegreesWithATipFlat) {
  const test::TempDir dir;
  const Made m = make(job_with_tools(dir, kSixty, with(kOutline, "tool = 12", "tool = 21")));
  ASSERT_TRUE(m.ok) << (m.diags.all().empty() ? "" : m.diags.all()[0].message);
  const Measured got = measure(m.tp);
  ASSERT_EQ(got.depths.size(), 1u);
  EXPECT_NEAR(got.depths[0], -(1.0 / tan_deg(30) + 0.5), 1e-9);  // -2.2321
  EXPECT_NEAR(got.offset, 0.3 + 0.5 * tan_deg(30), 1e-3);        // 0.5887
  EXPECT_NEAR(edge_width(got, 60, 0.6), 1.0, 1e-3);
}

TEST(Chamfer, NinetyDegreesWithATipFlat) {
  const test::TempDir dir;
  const Made m = make(job_with_tools(dir, kSixty, with(kOutline, "tool = 12", "tool = 22")));
  ASSERT_TRUE(m.ok) << (m.diags.all().empty() ? "" : m.diags.all()[0].message);
  const Measured got = measure(m.tp);
  EXPECT_NEAR(got.depths[0], -1.5, 1e-9);
  EXPECT_NEAR(got.offset, 1.0, 1e-3);
  EXPECT_NEAR(edge_width(got, 90, 1.0), 1.0, 1e-3);
}

TEST(Chamfer, InsideThePocketTheOffsetIsInward) {
  // The pocket's right edge is X65 (straight from Y29 to Y51).
  const Made m = make(with(with(job_text(kOutline), "OUTLINE", "POCKET"), "outside", "inside"));
  ASSERT_TRUE(m.ok) << (m.diags.all().empty() ? "" : m.diags.all()[0].message);
  double highest_x = -1e300;
  for (const canon::Op& op : m.tp.ops()) {
    const auto* f = std::get_if<canon::Feed>(&op.kind);
    if (f != nullptr && f->to.z < 0 && f->to.y > 29 && f->to.y < 51)
      highest_x = std::max(highest_x, f->to.x);
  }
  EXPECT_NEAR(highest_x, 64.5, 1e-3);
}

TEST(Chamfer, TheProgramSaysWhereTheTipAndThePathAre) {
  const Made m = make(job_text(kOutline));
  ASSERT_TRUE(m.ok);
  bool said = false;
  for (const canon::Op& op : m.tp.ops()) {
    if (const auto* c = std::get_if<canon::Comment>(&op.kind))
      said = said ||
             c->text.find("tip at Z-1.5000 = width/tan[45] + tip offset 0.5") != std::string::npos;
  }
  EXPECT_TRUE(said);
}

TEST(Chamfer, AutoTakesTheSmallestMillWhoseEdgeReaches) {
  const test::TempDir dir;
  // T22 (D8, tip D1) reaches 4 - 0.5 - 0.5 = 3; T21 (D12, 60 deg) 6 - 0.3 - 0.29 = 5.4.
  const std::string ops = with(kOutline, "tool = 12", "tool = \"auto\"");
  const Made small = make(job_with_tools(dir, kSixty, ops));
  ASSERT_TRUE(small.ok) << (small.diags.all().empty() ? "" : small.diags.all()[0].message);
  const auto changes = [](const canon::Toolpath& tp) {
    std::vector<int> out;
    for (const canon::Op& op : tp.ops()) {
      if (const auto* t = std::get_if<canon::ToolChange>(&op.kind)) out.push_back(t->tool);
    }
    return out;
  };
  EXPECT_EQ(changes(small.tp), (std::vector<int>{22}));
  const Made wide = make(job_with_tools(dir, kSixty, with(ops, "width = 1.0", "width = 4.0")));
  ASSERT_TRUE(wide.ok) << (wide.diags.all().empty() ? "" : wide.diags.all()[0].message);
  EXPECT_EQ(changes(wide.tp), (std::vector<int>{21}));
}

TEST(Chamfer, AWidthNoMillReachesIsAnErrorAtTheWidth) {
  // The shop's T12 reaches 4.5 mm with the default tip offset.
  for (const char* tool : {"tool = 12", "tool = \"auto\""}) {
    SCOPED_TRACE(tool);
    const Made m =
        make(with(with(job_text(kOutline), "tool = 12", tool), "width = 1.0", "width = 4.6"));
    EXPECT_FALSE(m.ok);
    const core::Diagnostic* d = find(m.diags, core::Code::JobNoToolFits);
    ASSERT_NE(d, nullptr);
    EXPECT_EQ(d->loc.line, kFirstOpLine + 4);
    EXPECT_NE(d->message.find("4.5"), std::string::npos) << d->message;
  }
}

TEST(Chamfer, ALibraryWithoutChamferMillsIsAnErrorAtTheTool) {
  const test::TempDir dir;
  const std::string flat =
      "[[tool]]\nnumber = 1\ntype = \"flat\"\ndiameter = 10.0\ncutting_length = 20.0\n"
      "material = \"carbide\"\n";
  const Made m = make(job_with_tools(dir, flat, with(kOutline, "tool = 12", "tool = \"auto\"")));
  EXPECT_FALSE(m.ok);
  const core::Diagnostic* d = find(m.diags, core::Code::JobNoToolFits);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->loc.line, kFirstOpLine + 5);
}

TEST(Chamfer, AnEndMillDoesNotChamfer) {
  const Made m = make(with(job_text(kOutline), "tool = 12", "tool = 1"));
  EXPECT_FALSE(m.ok);
  const core::Diagnostic* d = find(m.diags, core::Code::JobNoToolFits);
  ASSERT_NE(d, nullptr);
  EXPECT_NE(d->message.find("a chamfer mill"), std::string::npos) << d->message;
}

TEST(Chamfer, WithoutRpmAndFeedThereIsNoCuttingData) {
  const Made m = make(with(job_text(kOutline), "rpm = 8000\nfeed = 600\n", ""));
  EXPECT_FALSE(m.ok);
  const core::Diagnostic* d = find(m.diags, core::Code::JobNoCuttingData);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->loc.line, kFirstOpLine);
  EXPECT_NE(d->message.find("give rpm and feed"), std::string::npos) << d->message;
}

TEST(Chamfer, AChamferOffTheStockIsAnError) {
  std::string text = with(job_text(kOutline), "size = [130.0, 90.0, 10.0]",
                          "size = [130.0, 90.0, 10.0]\norigin = [500.0, 500.0]");
  const Made m = make(text);
  EXPECT_FALSE(m.ok);
  ASSERT_NE(find(m.diags, core::Code::JobOutsideStock), nullptr);
}

TEST(Chamfer, ATipBelowTheStocksBottomIsAWarningAtTheWidth) {
  const Made m =
      make(with(with(job_text(kOutline), "size = [130.0, 90.0, 10.0]", "size = [130.0, 90.0, 2.0]"),
                "width = 1.0", "width = 4.0"));
  EXPECT_TRUE(m.ok);  // 4.5 mm deep in 2 mm
  const core::Diagnostic* d = find(m.diags, core::Code::JobCutsBelowStock);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->loc.line, kFirstOpLine + 4);
  EXPECT_NE(d->message.find("the chamfer goes"), std::string::npos) << d->message;
}

// ---- bad keys ----

const core::Diagnostic* load_error(const std::string& text, core::Code code) {
  static std::unique_ptr<testing::Loaded> l;  // keeps the diagnostic alive for the caller
  l = load_text(text);
  EXPECT_FALSE(l->job);
  return find(l->diags, code);
}

TEST(ChamferKeys, ADepthIsRefusedWithTheReason) {
  const core::Diagnostic* d = load_error(
      with(job_text(kOutline), "width = 1.0\n", "width = 1.0\ndepth = 2.0\n"), core::Code::BadJob);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->loc.line, kFirstOpLine + 5);
  EXPECT_NE(d->message.find("follows from its width"), std::string::npos) << d->message;
}

TEST(ChamferKeys, TheWidthIsRequiredAndPositive) {
  const core::Diagnostic* missing =
      load_error(with(job_text(kOutline), "width = 1.0\n", ""), core::Code::BadJob);
  ASSERT_NE(missing, nullptr);
  EXPECT_NE(missing->message.find("width"), std::string::npos) << missing->message;
  const core::Diagnostic* zero =
      load_error(with(job_text(kOutline), "width = 1.0", "width = 0.0"), core::Code::BadJob);
  ASSERT_NE(zero, nullptr);
  EXPECT_EQ(zero->loc.line, kFirstOpLine + 4);
}

TEST(ChamferKeys, ANegativeTipOffsetIsAnError) {
  const core::Diagnostic* d =
      load_error(with(job_text(kOutline), "width = 1.0\n", "width = 1.0\ntip_offset = -0.5\n"),
                 core::Code::BadJob);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->loc.line, kFirstOpLine + 5);
}

TEST(ChamferKeys, TheSideOnIsAGrooveNotAChamfer) {
  const core::Diagnostic* d =
      load_error(with(job_text(kOutline), "\"outside\"", "\"on\""), core::Code::BadJob);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->loc.line, kFirstOpLine + 3);
}

TEST(ChamferKeys, AProfilesKeyIsUnknown) {
  const core::Diagnostic* d =
      load_error(with(job_text(kOutline), "width = 1.0\n", "width = 1.0\ntabs = 4\n"),
                 core::Code::UnknownJobKey);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->loc.line, kFirstOpLine + 5);
}

// ---- through the posts ----

TEST(Chamfer, ReadsBackTheSameInEveryControl) {
  const Made m = make(with(job_text(kOutline), "\"outside\"", "\"auto\""));
  ASSERT_TRUE(m.ok);
  for (const char* post : {"rs274ngc", "fanuc", "grbl", "romi"}) {
    SCOPED_TRACE(post);
    core::DiagnosticList diags;
    const std::string text = test::post_text(m.tp.ops(), post, diags);
    EXPECT_FALSE(diags.has_errors());
    if (const auto back = test::interpret_in(text, post))
      test::expect_same_path(m.tp.ops(), *back, 1e-3);
  }
}

}  // namespace
}  // namespace usina::job
