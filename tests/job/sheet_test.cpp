// The setup sheet (usina job --sheet; job/sheet.hpp): each step of the job
// with its tool, stick-out, speeds and time, the times adding up to stats'
// cycle time, the author's text escaped; and the sheet's file as safe as
// the program's (never an input, never the program, nothing when the job
// fails); the PDF sheet says what the HTML one says, on A4 pages, and its
// format is its extension's.
#include "job/sheet.hpp"

#include <filesystem>
#include <numbers>
#include <regex>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "canon/sink.hpp"
#include "job/make.hpp"
#include "job_test_util.hpp"
#include "sim/stats.hpp"
#include "support/files.hpp"
#include "support/pdf.hpp"
#include "support/usina_process.hpp"

namespace usina::job {
namespace {

using test::quote;

struct Made {
  std::unique_ptr<testing::Loaded> loaded;
  SheetLog log;
  std::unique_ptr<SheetTimer> timer;
};

std::unique_ptr<Made> made_with_sheet(const std::string& text) {
  auto m = std::make_unique<Made>();
  m->loaded = testing::load_text(text);
  EXPECT_TRUE(m->loaded->job) << m->loaded->io_error;
  if (!m->loaded->job) return m;
  m->timer = std::make_unique<SheetTimer>(sim::default_machine_profile(), m->log);
  canon::NullSink program;
  canon::TeeSink both({&program, m->timer.get()});
  EXPECT_TRUE(make_job(*m->loaded->job, both, m->loaded->diags, &m->log));
  m->timer->finish();
  return m;
}

const std::string kTwoOperations =
    "[[operation]]\ntype = \"pocket\"\nlayer = \"POCKET\"\ndepth = 4.0\nstep_down = 2.0\n"
    "tool = \"auto\"\n"
    "[[operation]]\ntype = \"profile\"\nlayer = \"OUTLINE\"\nside = \"outside\"\n"
    "depth = 10.5\nstep_down = 3.5\ntool = 1\n";

TEST(SetupSheet, EachOperationIsAStepWhoseTimesAddUpToTheCycleTime) {
  const auto m = made_with_sheet(testing::job_text(kTwoOperations));
  ASSERT_TRUE(m->timer);
  ASSERT_EQ(m->log.steps.size(), 2u);
  EXPECT_EQ(m->log.steps[0].depth, 4.0);
  EXPECT_EQ(m->log.steps[1].tool.number, 1);
  EXPECT_FALSE(m->log.steps[0].chosen.empty());  // tool = "auto" says why
  EXPECT_TRUE(m->log.steps[1].chosen.empty());   // a named tool
  double sum = 0.0;
  for (const SheetStep& s : m->log.steps) {
    EXPECT_GT(s.time.cutting_s, 0.0) << s.title;
    EXPECT_GT(s.rpm, 0.0);
    sum += s.time.total_s();
  }
  // Before the first step only the header's comments: nothing takes time.
  EXPECT_NEAR(sum, m->timer->report().total.total_s(), 1e-6);
}

TEST(SetupSheet, TheToolListGivesEachToolItsDeepestCutAndStickOut) {
  const auto m = made_with_sheet(testing::job_text(kTwoOperations));
  ASSERT_TRUE(m->timer);
  const std::string html = sheet_html(*m->loaded->job, m->log, *m->timer, "<svg></svg>", "p.ngc");
  // T1 cuts the profile 10.5 deep: 12.5 mm out of the holder at the least.
  const std::size_t t1 = html.find("<tr><td>T1</td>");
  ASSERT_NE(t1, std::string::npos) << html;
  const std::string row = html.substr(t1, html.find("</tr>", t1) - t1);
  EXPECT_NE(row.find("<td>10.5</td><td>12.5</td>"), std::string::npos) << row;
  EXPECT_NE(html.find("Cycle time"), std::string::npos);
  EXPECT_NE(html.find("no [cost] per_hour"), std::string::npos);  // the default profile has none
}

TEST(SetupSheet, ABoreIsAStepWithItsToolSetToTheHoleAndItsTime) {
  std::string text = testing::job_text(
      "[[operation]]\ntype = \"drill\"\nlayer = \"PILOT\"\ndepth = 13.0\ntool = \"auto\"\n"
      "[[operation]]\ntype = \"bore\"\nlayer = \"BORE\"\ndiameter = 10.0\ndepth = 9.0\n"
      "tool = \"auto\"\n");
  text.replace(text.find("plate.dxf"), 9, "bearing_plate.dxf");
  const auto m = made_with_sheet(text);
  ASSERT_TRUE(m->timer);
  ASSERT_EQ(m->log.steps.size(), 2u);
  const SheetStep& bore = m->log.steps[1];
  EXPECT_NE(bore.title.find("bore layer BORE: 2 holes D10"), std::string::npos) << bore.title;
  EXPECT_EQ(bore.tool.number, 13);
  EXPECT_DOUBLE_EQ(bore.tool.diameter, 10.0);  // the head as set, not its range
  EXPECT_EQ(bore.holes.size(), 2u);
  // Fed in and out 10 mm (R1 to Z-9) at fn*n = 0.0127 * 727.7 mm/min, twice
  // a hole: 4 * 10 / 9.242 min, at the least.
  EXPECT_GT(bore.time.cutting_s, 4 * 10 / (0.0127 * 22.86e3 / (std::numbers::pi * 10)) * 60);
  const std::string html = sheet_html(*m->loaded->job, m->log, *m->timer, "", "p.ngc");
  EXPECT_NE(html.find("<tr><td>T13</td>"), std::string::npos) << html;
  EXPECT_NE(html.find("bore"), std::string::npos);
}

TEST(SetupSheet, TheAuthorsTextIsEscaped) {
  std::string text = testing::job_text(kTwoOperations);
  text.replace(text.find("name = \"test\""), 13,
               "name = \"<script>alert(1)</script>\"\nsetup_note = \"vise & <b>jaws</b>\"");
  const auto m = made_with_sheet(text);
  ASSERT_TRUE(m->timer);
  const std::string html = sheet_html(*m->loaded->job, m->log, *m->timer, "", "p.ngc");
  EXPECT_EQ(html.find("<script>"), std::string::npos);
  EXPECT_NE(html.find("&lt;script&gt;alert(1)&lt;/script&gt;"), std::string::npos);
  EXPECT_NE(html.find("vise &amp; &lt;b&gt;jaws&lt;/b&gt;"), std::string::npos);
}

TEST(SetupSheetCli, ThePlateExampleWritesTheProgramAndItsSheet) {
  const test::TempDir dir;
  const std::string job = testing::repo("examples/jobs/plate.toml");
  const test::Run r =
      test::usina("job " + quote(job) + " --post fanuc -o " + quote(dir.path("plate.nc")) +
                  " --sheet " + quote(dir.path("plate.html")));
  ASSERT_EQ(r.status, 0) << r.err;
  ASSERT_TRUE(test::exists(dir.path("plate.nc")));
  const std::string html = test::slurp(dir.path("plate.html"));
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(html.find("<svg"), std::string::npos);
  EXPECT_EQ(html.find("<?xml"), std::string::npos);  // the SVG's declaration left out
  // Six holes seen from above: circles of their drills' diameters (D5 and D6.8).
  EXPECT_EQ(test::count(html, "<circle"), 6u) << html;
  EXPECT_NE(html.find("Setup sheet: plate"), std::string::npos);
  EXPECT_NE(html.find("an hour of the machine"), std::string::npos);  // small_vmc has a cost
}

TEST(SetupSheetCli, TheSheetIsNeverTheProgramNorAnInput) {
  const test::TempDir dir;
  // Named as a sheet may be: the rule refused is the input's, not the extension's.
  const std::string job = dir.write("job.html", testing::job_text(kTwoOperations));
  const std::string same = dir.path("same.html");
  test::Run r = test::usina("job " + quote(job) + " --post rs274ngc -o " + quote(same) +
                            " --sheet " + quote(same));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("the same file"), std::string::npos) << r.err;
  EXPECT_FALSE(test::exists(same));
  const std::string before = test::slurp(job);
  r = test::usina("job " + quote(job) + " --post rs274ngc -o " + quote(dir.path("p.ngc")) +
                  " --sheet " + quote(job));
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(test::slurp(job), before);
  EXPECT_FALSE(test::exists(dir.path("p.ngc")));  // refused before anything was written
}

TEST(SetupSheetCli, AJobWithAnErrorLeavesNoSheet) {
  const test::TempDir dir;
  const std::string job = dir.write(
      "job.toml", testing::job_text("[[operation]]\ntype = \"pocket\"\nlayer = \"NO_SUCH\"\n"
                                    "depth = 4.0\ntool = \"auto\"\n"));
  const test::Run r =
      test::usina("job " + quote(job) + " --post rs274ngc -o " + quote(dir.path("p.ngc")) +
                  " --sheet " + quote(dir.path("p.html")));
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_FALSE(test::exists(dir.path("p.html")));
  EXPECT_FALSE(test::exists(dir.path("p.ngc")));
}

// `usina job JOB --post fanuc -o DIR/p.nc --sheet DIR/SHEET`.
test::Run job_with_sheet(const std::string& job, const test::TempDir& dir,
                         const std::string& sheet) {
  return test::usina("job " + quote(job) + " --post fanuc -o " + quote(dir.path("p.nc")) +
                     " --sheet " + quote(dir.path(sheet)));
}

TEST(SetupSheetCli, ThePdfSheetHoldsTheToolsAndTheCycleTimeOfTheHtmlOne) {
  const test::TempDir dir;
  const std::string job = testing::repo("examples/jobs/plate.toml");
  test::Run r = job_with_sheet(job, dir, "plate.html");
  ASSERT_EQ(r.status, 0) << r.err;
  r = job_with_sheet(job, dir, "plate.pdf");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string pdf = test::slurp(dir.path("plate.pdf"));
  EXPECT_EQ(pdf.rfind("%PDF-", 0), 0u);
  // The title, the facts, the picture and the five tools on the first
  // page; the operations' rows, with their reasons, and the totals on the
  // second (measured: DejaVu Sans, Debian 12's cairo 1.16).
  EXPECT_EQ(test::pdf_pages(pdf), 2u);
  const std::string html = test::slurp(dir.path("plate.html"));
  const auto text = test::pdf_text(dir.path("plate.pdf"));
  if (!text) GTEST_SKIP() << "pdftotext (poppler-utils, scripts/setup.sh) is not installed";
  const std::regex tool_row("<tr><td>(T[0-9]+)</td><td>([^<(]+) \\(");
  std::size_t tools = 0;
  for (auto it = std::sregex_iterator(html.begin(), html.end(), tool_row);
       it != std::sregex_iterator(); ++it, ++tools) {
    EXPECT_NE(text->find((*it)[1].str()), std::string::npos) << (*it)[1];
    EXPECT_NE(text->find((*it)[2].str()), std::string::npos) << (*it)[2];
  }
  EXPECT_GE(tools, 4u) << html;
  std::smatch cycle;
  ASSERT_TRUE(std::regex_search(html, cycle, std::regex("Cycle time</th><td>([^(]+) \\(")));
  EXPECT_NE(text->find("Cycle time"), std::string::npos);
  EXPECT_NE(text->find(cycle[1].str()), std::string::npos) << cycle[1] << "\n" << *text;
  EXPECT_NE(text->find("an hour of the machine"), std::string::npos);
  EXPECT_NE(text->find("Setup sheet: plate — page 2"), std::string::npos);
}

TEST(SetupSheetCli, ALongSetupNoteCarriesOnToAnotherPage) {
  const test::TempDir dir;
  std::string note;
  for (int i = 1; i <= 120; ++i)
    note += fmt::format("clamp {} at the left jaw\\n", i);
  std::string text = testing::job_text(kTwoOperations);
  text.replace(text.find("name = \"test\""), 13, "name = \"test\"\nsetup_note = \"" + note + "\"");
  const std::string job = dir.write("job.toml", text);
  const std::string short_job = dir.write("short.toml", testing::job_text(kTwoOperations));
  ASSERT_EQ(job_with_sheet(short_job, dir, "short.pdf").status, 0);
  const test::Run r = job_with_sheet(job, dir, "long.pdf");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::size_t short_pages = test::pdf_pages(test::slurp(dir.path("short.pdf")));
  EXPECT_GE(short_pages, 1u);
  // 120 lines of 11 pt: more than a page of 758 pt on their own.
  EXPECT_GE(test::pdf_pages(test::slurp(dir.path("long.pdf"))), short_pages + 2);
  const auto pdf_text = test::pdf_text(dir.path("long.pdf"));
  if (!pdf_text) GTEST_SKIP() << "pdftotext (poppler-utils, scripts/setup.sh) is not installed";
  EXPECT_NE(pdf_text->find("clamp 1 at the left jaw"), std::string::npos);
  EXPECT_NE(pdf_text->find("clamp 120 at the left jaw"), std::string::npos);
}

TEST(SetupSheetCli, TheExtensionChoosesTheFormatAndAnyOtherIsRefused) {
  const test::TempDir dir;
  const std::string job = dir.write("job.toml", testing::job_text(kTwoOperations));
  for (const char* sheet : {"p.txt", "p", "p.pdf.bak", "p.svg"}) {
    const test::Run r = job_with_sheet(job, dir, sheet);
    EXPECT_EQ(r.status, 2) << sheet;
    EXPECT_NE(r.err.find("the extension chooses the sheet's format"), std::string::npos) << r.err;
    EXPECT_FALSE(test::exists(dir.path(sheet)));
    EXPECT_FALSE(test::exists(dir.path("p.nc")));  // refused before anything was written
  }
  ASSERT_EQ(job_with_sheet(job, dir, "upper.PDF").status, 0);
  EXPECT_EQ(test::slurp(dir.path("upper.PDF")).rfind("%PDF-", 0), 0u);
  ASSERT_EQ(job_with_sheet(job, dir, "page.htm").status, 0);
  EXPECT_EQ(test::slurp(dir.path("page.htm")).rfind("<!DOCTYPE html>", 0), 0u);
}

TEST(SetupSheetCli, AJobWithAnErrorLeavesAnOldPdfSheetAsItWas) {
  const test::TempDir dir;
  const std::string job = dir.write(
      "job.toml", testing::job_text("[[operation]]\ntype = \"pocket\"\nlayer = \"NO_SUCH\"\n"
                                    "depth = 4.0\ntool = \"auto\"\n"));
  const std::string old = dir.write("p.pdf", "the sheet of yesterday");
  const test::Run r = job_with_sheet(job, dir, "p.pdf");
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_EQ(test::slurp(old), "the sheet of yesterday");
  EXPECT_FALSE(test::exists(dir.path("p.nc")));
  const test::Run fresh = job_with_sheet(job, dir, "new.pdf");
  EXPECT_EQ(fresh.status, 1);
  EXPECT_FALSE(test::exists(dir.path("new.pdf")));
}

TEST(SetupSheetCli, APdfSheetIsNeverAnInput) {
  const test::TempDir dir;
  const std::string job = dir.write("job.pdf", testing::job_text(kTwoOperations));
  const std::string before = test::slurp(job);
  const test::Run r = test::usina("job " + quote(job) + " --post fanuc -o " +
                                  quote(dir.path("p.nc")) + " --sheet " + quote(job));
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(test::slurp(job), before);
  EXPECT_FALSE(test::exists(dir.path("p.nc")));
}

// docs/cli.md's rules for every output: a folder is refused before
// anything is written; a character device is written in place, never
// replaced.
TEST(SetupSheetCli, APdfSheetFollowsTheOutputRulesForAFolderAndADevice) {
  const test::TempDir dir;
  const std::string job = dir.write("job.toml", testing::job_text(kTwoOperations));
  std::filesystem::create_directory(dir.path("folder.pdf"));
  test::Run r = job_with_sheet(job, dir, "folder.pdf");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_FALSE(test::exists(dir.path("p.nc")));
  EXPECT_TRUE(std::filesystem::is_directory(dir.path("folder.pdf")));
  std::filesystem::create_symlink("/dev/null", dir.path("null.pdf"));
  r = job_with_sheet(job, dir, "null.pdf");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(std::filesystem::is_symlink(dir.path("null.pdf")));
  EXPECT_TRUE(std::filesystem::is_character_file("/dev/null"));
}

}  // namespace
}  // namespace usina::job
