// A LinuxCNC tool table as a job's tool library (docs/job.md, "A LinuxCNC
// tool table as the library"; job/tool_table_library.hpp): the number and
// diameter from the table, the rest from each tool's comment, every gap or
// contradiction an error at the table's file and line.
#include "job/tool_table_library.hpp"

#include <string>

#include <gtest/gtest.h>

#include "canon/toolpath.hpp"
#include "job/make.hpp"
#include "job_test_util.hpp"
#include "support/files.hpp"

namespace usina::job {
namespace {

using core::Code;
using testing::find;

struct Loaded {
  test::TempDir dir;
  core::SourceManager sources;
  core::DiagnosticList diags;
  std::optional<LoadedJob> job;
  std::string io_error;
};

// The plate's job with `table` as its library and `units` its
// tool_table_units line (none when empty); then `ops`.
std::unique_ptr<Loaded> load(const std::string& table, const std::string& units = "\"mm\"",
                             const std::string& ops = "") {
  auto l = std::make_unique<Loaded>();
  const std::string tbl = l->dir.write("shop.tbl", table);
  std::string text = testing::job_text(
      ops.empty() ? "[[operation]]\ntype = \"drill\"\nlayer = \"HOLES\"\ndepth = 12.0\n"
                    "diameter = 6.8\ntool = \"auto\"\n"
                  : ops);
  const std::string shop = testing::repo("examples/tools/shop.toml");
  text.replace(text.find(shop), shop.size(), tbl);
  if (!units.empty())
    text.replace(text.find("[stock]"), 7, "tool_table_units = " + units + "\n[stock]");
  l->job = load_job(l->dir.write("job.toml", text), l->sources, l->diags, l->io_error);
  return l;
}

const std::string kGood =
    "; the shop's table\n"
    "T1 P1 D10.0 Z72.0 ;10 mm 3-flute flat carbide cutting_length=22\n"
    "T5 P5 D6.8 ;6.8 mm jobber drill, hss, cutting_length=69\n"
    "T12 P12 D10 ;chamfer mill z4 carbide angle=90 cutting_length=5\n";

TEST(ToolTableLibrary, TheTableGivesNumberAndDiameterTheCommentTheRest) {
  const auto l = load(kGood);
  ASSERT_TRUE(l->job) << (l->diags.all().empty() ? l->io_error : l->diags.all()[0].message);
  const std::vector<Tool>& tools = l->job->tools;
  ASSERT_EQ(tools.size(), 3u);
  EXPECT_EQ(tools[0].number, 1);
  EXPECT_EQ(tools[0].type, ToolType::Flat);
  EXPECT_EQ(tools[0].flutes, 3);
  EXPECT_EQ(tools[0].material, ToolMaterial::Carbide);
  EXPECT_DOUBLE_EQ(tools[0].cutting_length, 22.0);
  EXPECT_EQ(tools[1].type, ToolType::Drill);
  EXPECT_EQ(tools[1].material, ToolMaterial::Hss);
  EXPECT_DOUBLE_EQ(tools[1].diameter, 6.8);
  EXPECT_EQ(tools[2].type, ToolType::Chamfer);
  EXPECT_EQ(tools[2].flutes, 4);
  EXPECT_DOUBLE_EQ(tools[2].angle, 90.0);
  // The job runs on it: the D6.8 drill chosen from the table.
  canon::Toolpath tp;
  core::DiagnosticList d;
  ASSERT_TRUE(make_job(*l->job, tp, d)) << (d.all().empty() ? "" : d.all()[0].message);
  bool changed_to_5 = false;
  for (const canon::Op& op : tp.ops()) {
    if (const auto* t = std::get_if<canon::ToolChange>(&op.kind)) changed_to_5 |= t->tool == 5;
  }
  EXPECT_TRUE(changed_to_5);
}

TEST(ToolTableLibrary, AnInchTablesLengthsAreConverted) {
  const auto l = load("T5 P5 D0.2677 ;drill hss cutting_length=2.5\n", "\"inch\"");
  ASSERT_TRUE(l->job) << (l->diags.all().empty() ? l->io_error : l->diags.all()[0].message);
  EXPECT_NEAR(l->job->tools[0].diameter, 6.79958, 1e-9);
  EXPECT_DOUBLE_EQ(l->job->tools[0].cutting_length, 63.5);
}

// The first error: its code, its rendered place, a phrase of its message.
void expect_error(const std::string& table, Code code, const std::string& place,
                  const std::string& words, const std::string& units = "\"mm\"") {
  const auto l = load(table, units);
  EXPECT_FALSE(l->job);
  const core::Diagnostic* e = find(l->diags, code);
  ASSERT_NE(e, nullptr) << table << (l->diags.all().empty() ? "" : l->diags.all()[0].message);
  const std::string shown = core::render(*e, l->sources);
  EXPECT_NE(shown.find(place), std::string::npos) << shown;
  EXPECT_NE(e->message.find(words), std::string::npos) << e->message;
}

TEST(ToolTableLibrary, WhatNoneSaysIsAnErrorAtTheToolsLine) {
  expect_error("T1 P1 D10 ;carbide 3-flute cutting_length=22\n", Code::BadToolLibrary,
               "shop.tbl:1:", "tool 1: the table does not give its type");
  expect_error("T1 P1 D10 ;flat 3-flute cutting_length=22\n", Code::BadToolLibrary,
               "shop.tbl:1:", "its tool material");
  expect_error(";\nT1 P1 D10 ;flat carbide cutting_length=22\n", Code::BadToolLibrary,
               "shop.tbl:2:", "its flutes");
  expect_error("T1 P1 D10 ;flat carbide 3-flute\n", Code::BadToolLibrary,
               "shop.tbl:1:", "its cutting length");
  expect_error("T1 P1 ;flat carbide 3-flute cutting_length=22\n", Code::BadToolLibrary,
               "shop.tbl:1:", "no diameter: add its D word");
  expect_error("T12 P12 D10 ;chamfer z4 carbide cutting_length=5\n", Code::BadToolLibrary,
               "shop.tbl:1:", "included angle");
}

TEST(ToolTableLibrary, ACommentThatSaysTwoThingsIsNotClear) {
  expect_error("T5 P5 D6.8 ;drill tap hss cutting_length=69\n", Code::BadToolLibrary,
               "shop.tbl:1:", "gives its type twice, differently (\"drill\" and \"tap\")");
  expect_error("T5 P5 D6.8 ;drill hss carbide cutting_length=69\n", Code::BadToolLibrary,
               "shop.tbl:1:", "tool material twice");
  expect_error("T5 P5 D6.8 ;drill hss cutting_length=69 speed=3\n", Code::BadToolLibrary,
               "shop.tbl:1:", "speed= is not a key");
  expect_error("T5 P5 D6.8 ;drill hss cutting_length=long\n", Code::BadToolLibrary,
               "shop.tbl:1:", "cutting_length=long is not a positive number");
  expect_error("T5 P5 D6.8 ;type=reamer hss cutting_length=69\n", Code::BadToolLibrary,
               "shop.tbl:1:", "type=reamer");
  expect_error("T5 P5 D6.8 ;drill hss cutting_length=69 pitch=1.25\n", Code::BadToolLibrary,
               "shop.tbl:1:", "only a tap has a pitch");
}

TEST(ToolTableLibrary, ABadTableLineIsTheTableReadersError) {
  expect_error("T1 P1 D10 ;flat carbide 3-flute cutting_length=22\nT2 P2 Dx\n", Code::BadToolTable,
               "shop.tbl:2:", "");
}

TEST(ToolTableLibrary, TheJobSaysTheTablesUnits) {
  expect_error(kGood, Code::BadJob, "job.toml:3:", "tool_table_units = \"mm\" or \"inch\"", "");
  expect_error(kGood, Code::BadJob, "job.toml:", "give \"mm\" or \"inch\"", "\"cm\"");
  // Units for a TOML library are refused: its lengths are mm.
  const test::TempDir dir;
  std::string text = testing::job_text(
      "[[operation]]\ntype = \"drill\"\nlayer = \"HOLES\"\n"
      "depth = 12.0\ntool = \"auto\"\n");
  text.replace(text.find("[stock]"), 7, "tool_table_units = \"mm\"\n[stock]");
  core::SourceManager sources;
  core::DiagnosticList diags;
  std::string io;
  EXPECT_FALSE(load_job(dir.write("job.toml", text), sources, diags, io));
  ASSERT_NE(find(diags, Code::BadJob), nullptr);
  EXPECT_NE(find(diags, Code::BadJob)->message.find("is for a LinuxCNC tool table"),
            std::string::npos);
}

}  // namespace
}  // namespace usina::job
