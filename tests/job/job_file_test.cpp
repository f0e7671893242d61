// Bad job files: every one a diagnostic at the TOML line and column of what
// is wrong (issue 16, "every bad job file ... a diagnostic with the TOML line").
#include <cmath>
#include <tuple>

#include <gtest/gtest.h>

#include "canon/sink.hpp"
#include "canon/toolpath.hpp"
#include "job/make.hpp"
#include "job_test_util.hpp"

namespace usina::job {
namespace {

using testing::find;
using testing::job_text;
using testing::load_text;

using testing::kFirstOpLine;

const std::string kPocket =
    "[[operation]]\n"       // 10
    "type = \"pocket\"\n"   // 11
    "layer = \"POCKET\"\n"  // 12
    "depth = 3.0\n"         // 13
    "tool = 2\n";           // 14

TEST(JobFile, AGoodJobLoads) {
  const auto l = load_text(job_text(kPocket));
  ASSERT_TRUE(l->job) << (l->diags.all().empty() ? l->io_error : l->diags.all()[0].message);
  EXPECT_EQ(l->job->job.operations.size(), 1u);
  EXPECT_EQ(l->job->job.operations[0].tool, 2);
  EXPECT_EQ(l->job->job.operations[0].loc.line, kFirstOpLine);
}

TEST(JobFile, AnUnknownKeyIsAnErrorAtItsLineWithTheNearestName) {
  const auto l = load_text(job_text(kPocket + "stepovr = 2.0\n"));
  EXPECT_FALSE(l->job);
  const core::Diagnostic* d = find(l->diags, core::Code::UnknownJobKey);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->loc.line, kFirstOpLine + 5);
  EXPECT_EQ(d->loc.col, 1u);
  EXPECT_NE(d->message.find("did you mean `stepover`?"), std::string::npos) << d->message;
}

TEST(JobFile, AnUnknownOperationIsAnErrorAtItsType) {
  const auto l = load_text(job_text("[[operation]]\ntype = \"knurl\"\ndepth = 1.0\ntool = 1\n"));
  EXPECT_FALSE(l->job);
  const core::Diagnostic* d = find(l->diags, core::Code::JobUnknownOperation);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->loc.line, kFirstOpLine + 1);
  EXPECT_EQ(d->loc.col, 8u);
  EXPECT_NE(d->message.find("knurl"), std::string::npos);
}

TEST(JobFile, AWrongTypeIsAnErrorAtTheValue) {
  const auto l = load_text(job_text(
      "[[operation]]\ntype = \"pocket\"\nlayer = \"POCKET\"\ndepth = \"deep\"\ntool = 2\n"));
  EXPECT_FALSE(l->job);
  const core::Diagnostic* d = find(l->diags, core::Code::BadJob);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->loc.line, kFirstOpLine + 3);
  EXPECT_NE(d->message.find("depth must be a number"), std::string::npos) << d->message;
}

TEST(JobFile, ANumberOutOfRangeSaysTheRange) {
  const auto l = load_text(
      job_text("[[operation]]\ntype = \"pocket\"\nlayer = \"POCKET\"\ndepth = -3.0\ntool = 2\n"));
  const core::Diagnostic* d = find(l->diags, core::Code::BadJob);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->loc.line, kFirstOpLine + 3);
  EXPECT_NE(d->message.find("out of range"), std::string::npos) << d->message;
}

TEST(JobFile, AKeyOfTheOtherStockShapeIsAnError) {
  std::string text = job_text(kPocket);
  text.replace(text.find("size = "), 0, "diameter = 40.0\n");  // line 8 of a box
  const auto l = load_text(text);
  EXPECT_FALSE(l->job);
  const core::Diagnostic* d = find(l->diags, core::Code::BadJob);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->loc.line, 8u);
}

TEST(JobFile, NotTomlIsAnErrorAtTheFault) {
  const auto l = load_text(job_text("[[operation]\n"));
  EXPECT_FALSE(l->job);
  const core::Diagnostic* d = find(l->diags, core::Code::BadJob);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->loc.line, kFirstOpLine);
}

TEST(JobFile, NoOperationsIsAnError) {
  const auto l = load_text(job_text(""));
  EXPECT_FALSE(l->job);
  EXPECT_NE(find(l->diags, core::Code::BadJob), nullptr);
}

TEST(JobFile, AnUnknownMaterialIsAnErrorAtTheStocksMaterial) {
  const auto l = load_text(job_text(kPocket, "unobtainium"));
  EXPECT_FALSE(l->job);
  const core::Diagnostic* d = find(l->diags, core::Code::JobUnknownMaterial);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->loc.line, 9u);
  EXPECT_NE(d->message.find("aluminium-wrought"), std::string::npos) << d->message;
}

TEST(JobFile, AMissingToolLibraryIsAnIoError) {
  std::string text = job_text(kPocket);
  text.replace(text.find("shop.toml"), 9, "no_such_library.toml");
  const auto l = load_text(text);
  EXPECT_FALSE(l->job);
  EXPECT_NE(l->io_error.find("no_such_library.toml"), std::string::npos);
}

// What only making the job finds: the names the operations use.
bool make(const testing::Loaded& l, core::DiagnosticList& diags) {
  canon::NullSink sink;
  return make_job(*l.job, sink, diags);
}

TEST(JobFile, AnUnknownToolIsAnErrorAtTheToolKey) {
  std::string text = job_text(kPocket);
  text.replace(text.find("tool = 2"), 8, "tool = 77");
  const auto l = load_text(text);
  ASSERT_TRUE(l->job);
  core::DiagnosticList diags;
  EXPECT_FALSE(make(*l, diags));
  const core::Diagnostic* d = find(diags, core::Code::JobUnknownTool);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->loc.line, kFirstOpLine + 4);
  EXPECT_EQ(d->loc.col, 8u);
}

TEST(JobFile, AMissingLayerIsAnErrorAtTheLayerKey) {
  std::string text = job_text(kPocket);
  text.replace(text.find("\"POCKET\""), 8, "\"POCKETS\"");
  const auto l = load_text(text);
  ASSERT_TRUE(l->job);
  core::DiagnosticList diags;
  EXPECT_FALSE(make(*l, diags));
  const core::Diagnostic* d = find(diags, core::Code::JobMissingLayer);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->loc.line, kFirstOpLine + 2);
  EXPECT_NE(d->message.find("POCKETS"), std::string::npos);
}

TEST(JobFile, AToolTooShortForTheDepthIsAnError) {
  std::string text = job_text(kPocket);
  text.replace(text.find("tool = 2"), 8, "tool = 3");  // cuts 8 mm deep
  text.replace(text.find("depth = 3.0"), 11, "depth = 9.0");
  const auto l = load_text(text);
  ASSERT_TRUE(l->job);
  core::DiagnosticList diags;
  EXPECT_FALSE(make(*l, diags));
  const core::Diagnostic* d = find(diags, core::Code::JobNoToolFits);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->loc.line, kFirstOpLine + 4);
}

TEST(JobFile, ADrillDoesNotMillAPocket) {
  std::string text = job_text(kPocket);
  text.replace(text.find("tool = 2"), 8, "tool = 5");
  const auto l = load_text(text);
  ASSERT_TRUE(l->job);
  core::DiagnosticList diags;
  EXPECT_FALSE(make(*l, diags));
  const core::Diagnostic* d = find(diags, core::Code::JobNoToolFits);
  ASSERT_NE(d, nullptr);
  EXPECT_NE(d->message.find("T5 is a drill tool"), std::string::npos) << d->message;
}

TEST(JobFile, NoCuttingDataIsAnErrorThatSaysWhatToGive) {
  // The materials file has no drilling row for polycarbonate.
  const auto l = load_text(
      job_text("[[operation]]\ntype = \"drill\"\nlayer = \"HOLES\"\ndepth = 5.0\ntool = \"auto\"\n",
               "plastic-polycarbonate"));
  ASSERT_TRUE(l->job);
  core::DiagnosticList diags;
  EXPECT_FALSE(make(*l, diags));
  const core::Diagnostic* d = find(diags, core::Code::JobNoCuttingData);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->loc.line, kFirstOpLine);
  EXPECT_NE(d->message.find("give rpm and feed"), std::string::npos) << d->message;
}

TEST(JobFile, BelowTheChartsSmallestDiameterThereIsNoData) {
  // T3 is D3, below the chart's first column (1/8", 3.175 mm).
  const auto l = load_text(
      job_text("[[operation]]\ntype = \"ellipse_pocket\"\ncenter = [50.0, 40.0]\nrx = 20.0\n"
               "ry = 10.0\ndepth = 2.0\ntool = 3\n"));
  ASSERT_TRUE(l->job);
  core::DiagnosticList diags;
  EXPECT_FALSE(make(*l, diags));
  EXPECT_NE(find(diags, core::Code::JobNoCuttingData), nullptr);
}

TEST(JobFile, GivenSpeedsNeedNoCuttingData) {
  const auto l = load_text(
      job_text("[[operation]]\ntype = \"ellipse_pocket\"\ncenter = [50.0, 40.0]\nrx = 20.0\n"
               "ry = 10.0\ndepth = 2.0\ntool = 3\nrpm = 12000.0\nfeed = 500.0\n"));
  ASSERT_TRUE(l->job);
  core::DiagnosticList diags;
  EXPECT_TRUE(make(*l, diags)) << (diags.all().empty() ? "" : diags.all()[0].message);
}

TEST(JobFile, RpmWithoutFeedIsAnError) {
  const auto l = load_text(job_text(kPocket + "rpm = 12000.0\n"));
  EXPECT_FALSE(l->job);
  const core::Diagnostic* d = find(l->diags, core::Code::BadJob);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->loc.line, kFirstOpLine + 5);
}

TEST(JobFile, AFaceMillDoesNotEngraveAndAnEngraverDoesNotFace) {
  for (const auto& [type, tool, takes] :
       {std::tuple{"engrave\"\ntext = \"A\"\nat = [10.0, 10.0]", "10", "an engraver"},
        std::tuple{"face\"", "11", "a face mill"}}) {
    const auto l =
        load_text(job_text(std::string("[[operation]]\ntype = \"") + type +
                           "\ndepth = 0.5\nrpm = 9000\nfeed = 300\ntool = " + tool + "\n"));
    ASSERT_TRUE(l->job) << type;
    core::DiagnosticList diags;
    EXPECT_FALSE(make(*l, diags));
    const core::Diagnostic* d = find(diags, core::Code::JobNoToolFits);
    ASSERT_NE(d, nullptr) << type;
    EXPECT_NE(d->message.find(takes), std::string::npos) << d->message;
  }
}

TEST(JobFile, AnEngravingNeedsItsTextAndWhere) {
  const auto l = load_text(job_text("[[operation]]\ntype = \"engrave\"\ndepth = 0.2\ntool = 11\n"));
  EXPECT_FALSE(l->job);
  const core::Diagnostic* d = find(l->diags, core::Code::BadJob);
  ASSERT_NE(d, nullptr);
  EXPECT_NE(d->message.find("text"), std::string::npos) << d->message;
  const auto empty = load_text(job_text(
      "[[operation]]\ntype = \"engrave\"\ntext = \"\"\nat = [0.0, 0.0]\ndepth = 0.2\ntool = 11\n"));
  EXPECT_FALSE(empty->job);
  const core::Diagnostic* e = find(empty->diags, core::Code::BadJob);
  ASSERT_NE(e, nullptr);
  EXPECT_NE(e->message.find("nothing to engrave"), std::string::npos) << e->message;
  EXPECT_EQ(e->loc.line, kFirstOpLine + 2);
}

TEST(JobFile, ACharacterTheFontLacksIsAnErrorAtTheOperation) {
  const auto l = load_text(
      job_text("[[operation]]\ntype = \"engrave\"\ntext = \"caf\u00e9\"\nat = [0.0, 0.0]\n"
               "depth = 0.2\nrpm = 9000\nfeed = 300\ntool = 11\n"));
  ASSERT_TRUE(l->job);
  core::DiagnosticList diags;
  EXPECT_FALSE(make(*l, diags));
  ASSERT_TRUE(diags.has_errors());
  EXPECT_EQ(diags.all().back().loc.line, kFirstOpLine);
}

TEST(JobFile, AFacingOfTheStockFromItsCorner) {
  const auto l =
      load_text(job_text("[[operation]]\ntype = \"face\"\ndepth = 0.5\ntool = \"auto\"\n"));
  ASSERT_TRUE(l->job);
  core::DiagnosticList diags;
  canon::Toolpath tp;
  ASSERT_TRUE(make_job(*l->job, tp, diags)) << (diags.all().empty() ? "" : diags.all()[0].message);
  // The 130 x 90 stock from X0 Y0 (job_text gives no origin): the rows
  // run from 2 mm left of it to 2 mm right of it with the D50's radius.
  double lo = 1e300, hi = -1e300;
  for (const canon::Op& op : tp.ops()) {
    if (const auto* f = std::get_if<canon::Feed>(&op.kind)) {
      lo = std::min(lo, f->to.x);
      hi = std::max(hi, f->to.x);
    }
  }
  EXPECT_DOUBLE_EQ(lo, -27);
  EXPECT_DOUBLE_EQ(hi, 157);
}

TEST(JobFile, SpotDrillingCentresEveryHoleWithOneSpotDrill) {
  const auto l =
      load_text(job_text("[[operation]]\ntype = \"spot\"\nlayer = \"HOLES\"\ndepth = 2.0\n"
                         "rpm = 3000\nfeed = 300\ntool = \"auto\"\n"));
  ASSERT_TRUE(l->job);
  core::DiagnosticList diags;
  canon::Toolpath tp;
  ASSERT_TRUE(make_job(*l->job, tp, diags)) << (diags.all().empty() ? "" : diags.all()[0].message);
  int changes = 0, spot_depths = 0;
  for (const canon::Op& op : tp.ops()) {
    if (const auto* t = std::get_if<canon::ToolChange>(&op.kind)) {
      EXPECT_EQ(t->tool, 8);  // the D10 spot drill, for the D5 and the D6.8 holes
      ++changes;
    }
    // Each spot a drilling cycle's hole whose bottom is 2 mm down.
    if (const auto* h = std::get_if<canon::Hole>(&op.kind);
        h && std::abs(h->at.z - h->depth + 2) < 1e-9)
      ++spot_depths;
  }
  EXPECT_EQ(changes, 1);
  EXPECT_EQ(spot_depths, 6);  // the plate's six holes
}

TEST(JobFile, ASpotDrillWithoutDataOrTooNarrowIsAnError) {
  // The tables have no carbide drilling row: a carbide spot drill needs its speeds.
  const auto l = load_text(job_text(
      "[[operation]]\ntype = \"spot\"\nlayer = \"HOLES\"\ndepth = 2.0\ntool = \"auto\"\n"));
  ASSERT_TRUE(l->job);
  core::DiagnosticList diags;
  EXPECT_FALSE(make(*l, diags));
  EXPECT_NE(find(diags, core::Code::JobNoCuttingData), nullptr);
  // A drill is no spot drill.
  const auto drill =
      load_text(job_text("[[operation]]\ntype = \"spot\"\nlayer = \"HOLES\"\n"
                         "depth = 2.0\nrpm = 3000\nfeed = 300\ntool = 6\n"));
  ASSERT_TRUE(drill->job);
  core::DiagnosticList d2;
  EXPECT_FALSE(make(*drill, d2));
  const core::Diagnostic* d = find(d2, core::Code::JobNoToolFits);
  ASSERT_NE(d, nullptr);
  EXPECT_NE(d->message.find("a spot drill"), std::string::npos) << d->message;
}

TEST(JobFile, TappingTheM8HolesWithTheirTap) {
  const auto l =
      load_text(job_text("[[operation]]\ntype = \"tap\"\nlayer = \"HOLES\"\n"
                         "diameter = 6.8\ndepth = 10.0\nrpm = 300\ntool = \"auto\"\n"));
  ASSERT_TRUE(l->job) << (l->diags.all().empty() ? "" : l->diags.all()[0].message);
  core::DiagnosticList diags;
  canon::Toolpath tp;
  ASSERT_TRUE(make_job(*l->job, tp, diags)) << (diags.all().empty() ? "" : diags.all()[0].message);
  int reversals = 0, tool = 0;
  for (const canon::Op& op : tp.ops()) {
    if (const auto* t = std::get_if<canon::ToolChange>(&op.kind)) tool = t->tool;
    if (const auto* s = std::get_if<canon::Spindle>(&op.kind))
      reversals += s->dir == canon::SpindleDir::Ccw ? 1 : 0;
    if (const auto* f = std::get_if<canon::Feed>(&op.kind)) {
      EXPECT_DOUBLE_EQ(*f->f, 375.0);
    }
  }
  EXPECT_EQ(tool, 9);
  EXPECT_EQ(reversals, 4);  // the plate's four D6.8 holes
}

TEST(JobFile, ATapNeedsItsSpeedAndNoFeed) {
  const auto none = load_text(
      job_text("[[operation]]\ntype = \"tap\"\nlayer = \"HOLES\"\ndepth = 10.0\ntool = 9\n"));
  EXPECT_FALSE(none->job);
  const core::Diagnostic* d = find(none->diags, core::Code::BadJob);
  ASSERT_NE(d, nullptr);
  EXPECT_NE(d->message.find("needs rpm"), std::string::npos) << d->message;
  const auto fed =
      load_text(job_text("[[operation]]\ntype = \"tap\"\nlayer = \"HOLES\"\n"
                         "depth = 10.0\nrpm = 300\nfeed = 400\ntool = 9\n"));
  EXPECT_FALSE(fed->job);
  const core::Diagnostic* e = find(fed->diags, core::Code::BadJob);
  ASSERT_NE(e, nullptr);
  EXPECT_EQ(e->loc.line, kFirstOpLine + 5);
  EXPECT_NE(e->message.find("pitch x rpm"), std::string::npos) << e->message;
}

TEST(JobFile, HolesThatAreNoTapDrillOfTheTapAreAnError) {
  // The D5 holes are an M6's tap drill, not the M8's.
  const auto l =
      load_text(job_text("[[operation]]\ntype = \"tap\"\nlayer = \"HOLES\"\n"
                         "diameter = 5.0\ndepth = 10.0\nrpm = 300\ntool = 9\n"));
  ASSERT_TRUE(l->job);
  core::DiagnosticList diags;
  EXPECT_FALSE(make(*l, diags));
  const core::Diagnostic* d = find(diags, core::Code::JobNoToolFits);
  ASSERT_NE(d, nullptr);
  EXPECT_NE(d->message.find("tap drill"), std::string::npos) << d->message;
}

TEST(JobFile, ANamedTapWithoutItsPitchIsAnError) {
  const test::TempDir dir;
  const std::string tools =
      dir.write("tools.toml",
                "[[tool]]\nnumber = 9\ntype = \"tap\"\ndiameter = 8.0\ncutting_length = 20.0\n"
                "material = \"hss\"\n");
  std::string text = job_text(
      "[[operation]]\ntype = \"tap\"\nlayer = \"HOLES\"\n"
      "diameter = 6.8\ndepth = 10.0\nrpm = 300\ntool = 9\n");
  const std::string shop = testing::repo("examples/tools/shop.toml");
  text.replace(text.find(shop), shop.size(), tools);
  const auto l = load_text(text);
  ASSERT_TRUE(l->job) << (l->diags.all().empty() ? l->io_error : l->diags.all()[0].message);
  core::DiagnosticList diags;
  EXPECT_FALSE(make(*l, diags));
  const core::Diagnostic* d = find(diags, core::Code::JobNoToolFits);
  ASSERT_NE(d, nullptr);
  EXPECT_NE(d->message.find("T9 has no pitch"), std::string::npos) << d->message;
}

}  // namespace
}  // namespace usina::job
