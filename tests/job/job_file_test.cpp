// Bad job files: every one a diagnostic at the TOML line and column of what
// is wrong (issue 16, "every bad job file ... a diagnostic with the TOML line").
#include <gtest/gtest.h>

#include "canon/sink.hpp"
#include "job/make.hpp"
#include "job_test_util.hpp"

namespace usina::job {
namespace {

using testing::find;
using testing::job_text;
using testing::load_text;

// job_text's own lines come first: the operations start on line 10.
constexpr std::uint32_t kFirstOpLine = 10;

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

}  // namespace
}  // namespace usina::job
