// Boring in jobs (docs/job.md, "Boring"; issue 16): boring tools in the
// library, boring rows in the materials, the bore operation's checks (its
// pilot hole, its tool, the stock), its cutting values against hand-computed
// figures from the cited chart, and G85 as each control writes and reads it.
#include <algorithm>
#include <cstdio>
#include <numbers>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "../post/round_trip.hpp"
#include "canon/bare_hole.hpp"
#include "canon/toolpath.hpp"
#include "canon/trace_writer.hpp"
#include "job/make.hpp"
#include "job/materials.hpp"
#include "job/tools.hpp"
#include "job_test_util.hpp"

namespace usina::job {
namespace {

using core::Code;
using testing::find;
using testing::kFirstOpLine;

// The plate's [job] and [stock] (130 x 90 x 10 from X0 Y0) with the
// bearing plate's drawing: PILOT D8.5 at X25, 50, 75 Y30; BORE D10 at X25
// and X75, D12 at X50.
std::string bore_job(const std::string& ops, const std::string& material = "aluminium-wrought") {
  std::string text = testing::job_text(ops, material);
  const std::string from = "examples/jobs/plate.dxf";
  text.replace(text.find(from), from.size(), "examples/jobs/bearing_plate.dxf");
  return text;
}

const std::string kPilots =
    "[[operation]]\ntype = \"drill\"\nlayer = \"PILOT\"\ndepth = 13.0\ntool = \"auto\"\n";

std::string bore_op(const std::string& keys) {
  return "[[operation]]\ntype = \"bore\"\nlayer = \"BORE\"\n" + keys;
}

struct Made {
  std::unique_ptr<testing::Loaded> loaded;
  core::DiagnosticList diags;
  canon::Toolpath tp;
  bool ok = false;
};

std::unique_ptr<Made> make(const std::string& text) {
  auto m = std::make_unique<Made>();
  m->loaded = testing::load_text(text);
  if (!m->loaded->job) return m;
  m->ok = make_job(*m->loaded->job, m->tp, m->diags);
  return m;
}

std::string first_message(const core::DiagnosticList& d) {
  return d.all().empty() ? std::string() : d.all()[0].message;
}

// ---- the tool library ----

std::optional<std::vector<Tool>> library(const std::string& tool, core::DiagnosticList& d) {
  return read_tool_library(
      "[[tool]]\nnumber = 1\ntype = \"bore\"\ncutting_length = 20.0\n"
      "material = \"carbide\"\n" +
          tool,
      1, d);
}

TEST(BoreTool, AHeadHasARangeABarASetDiameter) {
  core::DiagnosticList d;
  const auto head = library("diameter_range = [8.0, 24.0]\n", d);
  ASSERT_TRUE(head) << first_message(d);
  EXPECT_DOUBLE_EQ((*head)[0].diameter, 8.0);
  EXPECT_DOUBLE_EQ((*head)[0].max_bore, 24.0);
  EXPECT_TRUE(bores((*head)[0], 8.0));
  EXPECT_TRUE(bores((*head)[0], 24.0));
  EXPECT_FALSE(bores((*head)[0], 24.1));
  const auto bar = library("diameter = 12.0\n", d);
  ASSERT_TRUE(bar);
  EXPECT_EQ((*bar)[0].max_bore, 0.0);
  EXPECT_TRUE(bores((*bar)[0], 12.004));
  EXPECT_FALSE(bores((*bar)[0], 12.01));
}

void expect_library_error(const std::string& tool, std::uint32_t line, const std::string& words) {
  core::DiagnosticList d;
  EXPECT_FALSE(library(tool, d));
  const core::Diagnostic* e = find(d, Code::BadToolLibrary);
  ASSERT_NE(e, nullptr) << tool;
  EXPECT_EQ(e->loc.line, line) << e->message;
  EXPECT_NE(e->message.find(words), std::string::npos) << e->message;
}

TEST(BoreTool, EveryBadSizeIsAnErrorAtItsLine) {
  expect_library_error("", 1, "needs diameter");
  expect_library_error("diameter = 12.0\ndiameter_range = [8.0, 24.0]\n", 7, "not both");
  expect_library_error("diameter_range = [24.0, 8.0]\n", 6, "not [smallest, largest]");
  expect_library_error("diameter_range = [8.0]\n", 6, "diameter_range");
  core::DiagnosticList d;
  EXPECT_FALSE(
      read_tool_library("[[tool]]\nnumber = 1\ntype = \"drill\"\ndiameter = 5.0\n"
                        "diameter_range = [4.0, 6.0]\ncutting_length = 20.0\n"
                        "material = \"hss\"\n",
                        1, d));
  ASSERT_NE(find(d, Code::BadToolLibrary), nullptr);
  EXPECT_EQ(find(d, Code::BadToolLibrary)->loc.line, 5u);
  EXPECT_NE(find(d, Code::BadToolLibrary)->message.find("only a boring tool"), std::string::npos);
}

Tool bore_tool_of(int number, double diameter, double cutting_length, double max_bore = 0) {
  Tool t;
  t.number = number;
  t.type = ToolType::Bore;
  t.diameter = diameter;
  t.cutting_length = cutting_length;
  t.max_bore = max_bore;
  return t;
}

TEST(BoreTool, TheChoiceTakesASetBarFirstThenTheStiffestHeadThatEntersThePilot) {
  const Tool small_head = bore_tool_of(1, 6, 30, 20);
  const Tool big_head = bore_tool_of(2, 9, 30, 20);
  const Tool bar = bore_tool_of(3, 12, 30);
  const std::vector<Tool> tools{small_head, big_head, bar};
  EXPECT_EQ(boring_tool(tools, 12, 10, 8.5).tool->number, 3);  // nothing to set
  EXPECT_EQ(boring_tool(tools, 14, 10, 10).tool->number, 2);   // the thicker bar enters
  const ToolChoice narrow = boring_tool(tools, 14, 10, 8.5);   // only the D6 bar enters
  ASSERT_NE(narrow.tool, nullptr);
  EXPECT_EQ(narrow.tool->number, 1);
  EXPECT_NE(narrow.why.find("enters the D8.5 pilot hole"), std::string::npos) << narrow.why;
  const ToolChoice none = boring_tool({big_head}, 14, 10, 8.5);
  EXPECT_EQ(none.tool, nullptr);
  EXPECT_NE(none.why.find("does not enter the D8.5 pilot hole"), std::string::npos) << none.why;
  const ToolChoice deep = boring_tool(tools, 12, 40, 8.5);
  EXPECT_EQ(deep.tool, nullptr);
  EXPECT_NE(deep.why.find("cuts 30 mm deep at most"), std::string::npos) << deep.why;
  EXPECT_NE(boring_tool(tools, 30, 10, 0).why.find("no boring tool for D30"), std::string::npos);
}

// ---- the materials ----

TEST(BoreMaterials, ABoreRowFeedsPerRevolution) {
  core::DiagnosticList d;
  const auto ms = read_materials(
      "[[material]]\nname = \"m\"\n[[material.cutting]]\ntool = \"carbide\"\ncut = \"bore\"\n"
      "vc = 22.86\nfn = [[0.381, 0.0127]]\nsource = \"s\"\n",
      1, d);
  ASSERT_TRUE(ms) << first_message(d);
  ASSERT_EQ((*ms)[0].rows.size(), 1u);
  EXPECT_EQ((*ms)[0].rows[0].cut, CutKind::Bore);
}

TEST(BoreMaterials, ABoreRowWithAFeedPerToothOrAnUnknownCutIsRefused) {
  for (const auto& [row, line, words] :
       std::vector<std::tuple<std::string, std::uint32_t, std::string>>{
           {"cut = \"bore\"\nfz = [[0.381, 0.0127]]\n", 3, "needs fn"},
           {"cut = \"bore\"\nfn = [[0.381, 0.0127]]\nfz = [[1.0, 0.01]]\n", 7, "not fz"},
           {"cut = \"ream\"\nfn = [[0.381, 0.0127]]\n", 5, "\"bore\""}}) {
    core::DiagnosticList d;
    EXPECT_FALSE(
        read_materials("[[material]]\nname = \"m\"\n[[material.cutting]]\ntool = "
                       "\"carbide\"\n" +
                           row + "vc = 22.86\nsource = \"s\"\n",
                       1, d));
    const core::Diagnostic* e = find(d, Code::BadMaterials);
    ASSERT_NE(e, nullptr) << row;
    EXPECT_EQ(e->loc.line, line) << e->message;
    EXPECT_NE(e->message.find(words), std::string::npos) << e->message;
  }
}

// The shipped rows, by hand from SCT's chart: aluminium, uncoated carbide,
// 75 SFM = 22.86 m/min and .0005 in/rev = 0.0127 mm; AlTiN+ 250 SFM = 76.2.
TEST(BoreMaterials, TheShippedRowsAreTheChartsLowEnds) {
  core::DiagnosticList d;
  const auto l = testing::load_text(bore_job(kPilots));
  ASSERT_TRUE(l->job);
  const Material& al = l->job->materials[l->job->material];
  Tool carbide = bore_tool_of(1, 10, 30);
  carbide.material = ToolMaterial::Carbide;
  Tool coated = carbide;
  coated.material = ToolMaterial::Coated;
  const CuttingRow* c = cutting_row(al, carbide, CutKind::Bore);
  const CuttingRow* k = cutting_row(al, coated, CutKind::Bore);
  ASSERT_NE(c, nullptr);
  ASSERT_NE(k, nullptr);
  EXPECT_DOUBLE_EQ(c->vc, 75 * 0.3048);
  EXPECT_DOUBLE_EQ(k->vc, 250 * 0.3048);
  const auto cc = cutting_conditions(*c, carbide, false, {});
  ASSERT_TRUE(cc);
  EXPECT_NEAR(cc->rpm, 22.86 * 1000 / (std::numbers::pi * 10), 1e-9);  // 727.7
  EXPECT_NEAR(cc->feed, 0.0127 * cc->rpm, 1e-9);                       // 9.24
  EXPECT_DOUBLE_EQ(cc->plunge_feed, cc->feed);
}

// ---- the operation ----

TEST(BoreJob, PilotHolesThenBoresWithTheHeadAndTheSetBar) {
  const auto m = make(bore_job(kPilots + bore_op("depth = 9.0\ntool = \"auto\"\n")));
  ASSERT_TRUE(m->loaded->job) << first_message(m->loaded->diags);
  ASSERT_TRUE(m->ok) << first_message(m->diags);
  std::vector<int> tools;
  std::vector<canon::Hole> bores;
  std::vector<std::string> comments;
  for (const canon::Op& op : m->tp.ops()) {
    if (const auto* t = std::get_if<canon::ToolChange>(&op.kind)) tools.push_back(t->tool);
    if (const auto* h = std::get_if<canon::Hole>(&op.kind); h && h->cycle == canon::HoleCycle::Bore)
      bores.push_back(*h);
    if (const auto* c = std::get_if<canon::Comment>(&op.kind)) comments.push_back(c->text);
  }
  // The D8.5 drill; the head set to D10 (the bar is set to 12); the bar.
  EXPECT_EQ(tools, (std::vector<int>{7, 13, 14}));
  ASSERT_EQ(bores.size(), 3u);
  EXPECT_DOUBLE_EQ(bores[0].diameter, 10.0);
  EXPECT_DOUBLE_EQ(bores[2].diameter, 12.0);
  EXPECT_DOUBLE_EQ(bores[2].at.z - bores[2].depth, -9.0);
  const auto has = [&](const std::string& words) {
    return std::any_of(comments.begin(), comments.end(),
                       [&](const std::string& c) { return c.find(words) != std::string::npos; });
  };
  EXPECT_TRUE(has("set the boring head T13 (D8-24) to D10.000"));
  EXPECT_TRUE(has("pilot holes D8.5, drilled before"));
  EXPECT_TRUE(has("n = vc*1000/[pi*D] = 22.86*1000/[pi*10] = 728 rev/min"));
  EXPECT_TRUE(has("vf = fn*n = 0.0127*728 = 9 mm/min"));
  EXPECT_TRUE(has("[4] SCT solid carbide boring bar chart, Aluminum 100 HB, AlTiN+ coated"));
}

void expect_job_error(const std::string& text, Code code, std::uint32_t line,
                      const std::string& words) {
  const auto m = make(text);
  ASSERT_TRUE(m->loaded->job) << first_message(m->loaded->diags);
  EXPECT_FALSE(m->ok);
  const core::Diagnostic* e = find(m->diags, code);
  ASSERT_NE(e, nullptr) << first_message(m->diags);
  EXPECT_EQ(e->loc.line, line) << e->message;
  EXPECT_NE(e->message.find(words), std::string::npos) << e->message;
}

TEST(BoreJob, AHoleNoEarlierOperationDrilledIsRefusedAtTheLayer) {
  expect_job_error(bore_job(bore_op("depth = 9.0\ntool = \"auto\"\n")), Code::JobPilotHole,
                   kFirstOpLine + 2, "drilled by no earlier operation");
}

TEST(BoreJob, PredrilledHolesNeedNoPilot) {
  const auto m =
      make(bore_job(bore_op("depth = 9.0\ntool = 13\ndiameter = 10.0\n"
                            "predrilled = true\n")));
  ASSERT_TRUE(m->ok) << first_message(m->diags);
}

// A job the reader refuses: its first diagnostic of `code` at `line`.
void expect_read_error(const std::string& text, Code code, std::uint32_t line,
                       const std::string& words) {
  const auto l = testing::load_text(text);
  EXPECT_FALSE(l->job);
  const core::Diagnostic* e = find(l->diags, code);
  ASSERT_NE(e, nullptr);
  EXPECT_EQ(e->loc.line, line);
  EXPECT_NE(e->message.find(words), std::string::npos) << e->message;
}

TEST(BoreJob, PredrilledIsTrueOrFalse) {
  expect_read_error(bore_job(bore_op("depth = 9.0\ntool = 13\npredrilled = 1\n")), Code::BadJob,
                    kFirstOpLine + 5, "true or false");
}

TEST(BoreJob, APilotAsWideAsTheBoreLeavesNothingToBore) {
  // The D10 holes bored, then bored again to D10.
  const std::string ops = kPilots + bore_op("depth = 9.0\ntool = 13\ndiameter = 10.0\n");
  expect_job_error(bore_job(ops + bore_op("depth = 9.0\ntool = 13\ndiameter = 10.0\n")),
                   Code::JobPilotHole, kFirstOpLine + 5 + 6 + 2, "nothing is left to bore");
}

TEST(BoreJob, ABoreDeeperThanThePilotsFullDiameterIsRefused) {
  // D8.5 drilled 8 deep: full width to 8 - 2.55 = 5.45 mm.
  const std::string pilots =
      "[[operation]]\ntype = \"drill\"\nlayer = \"PILOT\"\ndepth = 8.0\ntool = \"auto\"\n";
  expect_job_error(bore_job(pilots + bore_op("depth = 6.0\ntool = \"auto\"\n")), Code::JobPilotHole,
                   kFirstOpLine + 5 + 2, "full width to 5.45 mm deep");
  const auto ok = make(bore_job(pilots + bore_op("depth = 5.4\ntool = \"auto\"\n")));
  EXPECT_TRUE(ok->ok) << first_message(ok->diags);
}

TEST(BoreJob, ANamedToolMustBoreTheHolesAndEnterThePilot) {
  // T5 is a drill; T14 is set to 12, the holes are D10; T13's bar needs D8.
  expect_job_error(bore_job(kPilots + bore_op("depth = 9.0\ndiameter = 10.0\ntool = 5\n")),
                   Code::JobNoToolFits, kFirstOpLine + 5 + 5, "a boring bar or head");
  expect_job_error(bore_job(kPilots + bore_op("depth = 9.0\ndiameter = 10.0\ntool = 14\n")),
                   Code::JobNoToolFits, kFirstOpLine + 5 + 5, "set to D12");
  const std::string small_pilots =
      "[[operation]]\ntype = \"drill\"\nlayer = \"PILOT\"\ndepth = 13.0\ntool = \"auto\"\n"
      "diameter = 8.5\n";
  const auto m =
      make(bore_job(small_pilots + bore_op("depth = 9.0\ndiameter = 10.0\ntool = 13\n")));
  EXPECT_TRUE(m->ok) << first_message(m->diags);
  expect_job_error(bore_job(bore_op("depth = 40.0\ndiameter = 10.0\ntool = 13\n"
                                    "predrilled = true\n")),
                   Code::JobNoToolFits, kFirstOpLine + 5, "cuts 25 mm deep at most");
}

TEST(BoreJob, AHeadIsSetOnceTheJobWritesNoStopToSetItAgain) {
  // T13 bores the D10 holes, then is asked for the D12.
  expect_job_error(bore_job(kPilots + bore_op("depth = 9.0\ntool = 13\ndiameter = 10.0\n") +
                            bore_op("depth = 9.0\ntool = 13\ndiameter = 12.0\n")),
                   Code::JobNoToolFits, kFirstOpLine + 5 + 6 + 4,
                   "writes no stop to set it again to D12");
}

TEST(BoreJob, TheStockChecksApply) {
  // 11.5 mm in a 10 mm stock: more than the 1 mm a through bore needs.
  const auto m =
      make(bore_job(bore_op("depth = 11.5\ntool = 13\ndiameter = 10.0\n"
                            "predrilled = true\n")));
  ASSERT_TRUE(m->ok) << first_message(m->diags);
  const core::Diagnostic* w = find(m->diags, Code::JobCutsBelowStock);
  ASSERT_NE(w, nullptr);
  EXPECT_EQ(w->loc.line, kFirstOpLine + 3);
  EXPECT_NE(w->message.find("give depth 11 at most"), std::string::npos) << w->message;
  const auto in =
      make(bore_job(bore_op("depth = 10.5\ntool = 13\ndiameter = 10.0\n"
                            "predrilled = true\n")));
  EXPECT_EQ(find(in->diags, Code::JobCutsBelowStock), nullptr);
  // The stock moved off the holes.
  std::string off =
      bore_job(bore_op("depth = 5.0\ntool = 13\ndiameter = 10.0\n"
                       "predrilled = true\n"));
  off.replace(off.find("[stock]\n"), 8, "[stock]\norigin = [40.0, 0.0]\n");
  expect_job_error(off, Code::JobOutsideStock, kFirstOpLine + 1 + 2, "");
}

TEST(BoreJob, NoBoringRowMeansRpmAndFeedAreGiven) {
  expect_job_error(bore_job(bore_op("depth = 5.0\ntool = 13\ndiameter = 10.0\npredrilled = true\n"),
                            "plastic-polycarbonate"),
                   Code::JobNoCuttingData, kFirstOpLine, "no boring data");
  const auto m = make(bore_job(bore_op("depth = 5.0\ntool = 13\ndiameter = 10.0\n"
                                       "predrilled = true\nrpm = 1500\nfeed = 60\n"),
                               "plastic-polycarbonate"));
  EXPECT_TRUE(m->ok) << first_message(m->diags);
}

TEST(BoreJob, ABoreIsNotPecked) {
  expect_read_error(bore_job(bore_op("depth = 5.0\ntool = 13\npeck = 1.0\n")), Code::UnknownJobKey,
                    kFirstOpLine + 5, "peck");
}

// ---- the posts ----

canon::Toolpath bored(const std::string& ops) {
  const auto m = make(bore_job(ops));
  EXPECT_TRUE(m->ok) << first_message(m->diags);
  return std::move(m->tp);
}

TEST(BorePost, G85WhereTheControlHasItMovesWhereNot) {
  const canon::Toolpath tp =
      bored(bore_op("depth = 9.0\ntool = 13\ndiameter = 10.0\npredrilled = true\n"));
  for (const char* post : {"rs274ngc", "fanuc"}) {
    core::DiagnosticList d;
    const std::string text = test::post_text(tp.ops(), post, d);
    EXPECT_NE(text.find("G85 X25"), std::string::npos) << post << "\n" << text;
    EXPECT_NE(text.find("Z-9"), std::string::npos) << text;
    EXPECT_EQ(text.find("G81"), std::string::npos) << text;
  }
  for (const char* post : {"grbl", "romi"}) {
    core::DiagnosticList d;
    const std::string text = test::post_text(tp.ops(), post, d);
    EXPECT_EQ(text.find("G85"), std::string::npos) << post << "\n" << text;
  }
}

// Each control's program read back feeds out of every hole: after the feed
// to the bottom, a feed (not a rapid) up to R.
TEST(BorePost, EveryControlFeedsOutOfTheBore) {
  const canon::Toolpath tp =
      bored(bore_op("depth = 9.0\ntool = 13\ndiameter = 10.0\npredrilled = true\n"));
  for (const char* post : {"rs274ngc", "fanuc", "grbl", "romi"}) {
    SCOPED_TRACE(post);
    core::DiagnosticList d;
    const auto back = test::interpret_in(test::post_text(tp.ops(), post, d), post);
    ASSERT_TRUE(back);
    int fed_out = 0;
    bool at_bottom = false;
    for (const canon::Op& op : *back) {
      if (const auto* f = std::get_if<canon::Feed>(&op.kind)) {
        if (at_bottom && std::abs(f->to.z - 1.0) < 1e-3) ++fed_out;
        at_bottom = std::abs(f->to.z + 9.0) < 1e-3;
      } else if (canon::is_motion(op.kind)) {
        at_bottom = false;
      }
    }
    EXPECT_EQ(fed_out, 2);
  }
}

// The text trace of one hole op.
std::string traced(const canon::Hole& h) {
  std::FILE* f = std::tmpfile();
  {
    canon::TraceWriter w(f, canon::TraceFormat::Text);
    w.on(canon::Op{h, {}, canon::Origin::Program});
  }
  std::fflush(f);
  std::rewind(f);
  std::string out;
  for (int c = std::fgetc(f); c != EOF; c = std::fgetc(f))
    out += static_cast<char>(c);
  std::fclose(f);
  return out;
}

TEST(BorePost, TheTraceSaysAHoleIsBored) {
  canon::Hole h{{1, 2, 1}, 10, 10, canon::HoleCycle::Bore};
  EXPECT_NE(traced(h).find("bored"), std::string::npos) << traced(h);
  h.cycle = canon::HoleCycle::Drill;
  EXPECT_EQ(traced(h).find("bored"), std::string::npos) << traced(h);
}

// ---- G89 and G86 (the `cycle` key) ----

TEST(BoreCycle, TheCycleIsG85G89OrG86) {
  expect_read_error(bore_job(bore_op("depth = 9.0\ntool = 13\ncycle = \"G81\"\n")), Code::BadJob,
                    kFirstOpLine + 5, "give \"G85\" (fed out, the default)");
  expect_read_error(bore_job(bore_op("depth = 9.0\ntool = 13\ncycle = 89\n")), Code::BadJob,
                    kFirstOpLine + 5, "cycle");
}

TEST(BoreCycle, G89NeedsItsDwellAndOnlyG89HasOne) {
  expect_read_error(bore_job(bore_op("depth = 9.0\ntool = 13\ncycle = \"G89\"\n")), Code::BadJob,
                    kFirstOpLine + 5, "give dwell = the seconds");
  expect_read_error(bore_job(bore_op("depth = 9.0\ntool = 13\ndwell = 0.5\n")), Code::BadJob,
                    kFirstOpLine + 5, "only G89 dwells");
  expect_read_error(bore_job(bore_op("depth = 9.0\ntool = 13\ncycle = \"G86\"\ndwell = 0.5\n")),
                    Code::BadJob, kFirstOpLine + 6, "only G89 dwells");
  // A drill has no dwell key at all.
  expect_read_error(bore_job("[[operation]]\ntype = \"drill\"\nlayer = \"PILOT\"\ndepth = 13.0\n"
                             "tool = \"auto\"\ndwell = 0.5\n"),
                    Code::UnknownJobKey, kFirstOpLine + 5, "dwell");
}

TEST(BoreCycle, TheDwellIsAboveZeroAndAtMostAMinute) {
  for (const char* dwell : {"0.0", "-1.0", "61.0", "500.0"}) {
    SCOPED_TRACE(dwell);
    expect_read_error(bore_job(bore_op(std::string("depth = 9.0\ntool = 13\ncycle = \"G89\"\n"
                                                   "dwell = ") +
                                       dwell + "\n")),
                      Code::BadJob, kFirstOpLine + 6, "dwell");
  }
  const auto m =
      make(bore_job(bore_op("depth = 9.0\ntool = 13\ndiameter = 10.0\npredrilled = "
                            "true\ncycle = \"G89\"\ndwell = 60.0\n")));
  EXPECT_TRUE(m->ok) << first_message(m->diags);
}

const std::string kDwellBore = bore_op(
    "depth = 9.0\ntool = 13\ndiameter = 10.0\npredrilled = true\ncycle = \"G89\"\ndwell = 0.5\n");
const std::string kStopBore =
    bore_op("depth = 9.0\ntool = 13\ndiameter = 10.0\npredrilled = true\ncycle = \"G86\"\n");

TEST(BoreCycle, TheHolesCarryTheCycleAndTheDwell) {
  for (const auto& [ops, cycle, dwell] : {std::tuple{kDwellBore, canon::HoleCycle::BoreDwell, 0.5},
                                          std::tuple{kStopBore, canon::HoleCycle::BoreStop, 0.0}}) {
    const canon::Toolpath tp = bored(ops);
    int holes = 0;
    for (const canon::Op& op : tp.ops()) {
      const auto* h = std::get_if<canon::Hole>(&op.kind);
      if (h == nullptr) continue;
      ++holes;
      EXPECT_EQ(h->cycle, cycle);
      EXPECT_DOUBLE_EQ(h->dwell, dwell);
      ASSERT_TRUE(h->f);
    }
    EXPECT_EQ(holes, 2);
  }
}

std::string posted(const canon::Toolpath& tp, const char* post) {
  core::DiagnosticList d;
  std::string text = test::post_text(tp.ops(), post, d);
  EXPECT_FALSE(d.has_errors()) << post << ": " << first_message(d);
  return text;
}

// G89 in G99, so LinuxCNC's feeds out to R as a Fanuc's does, then a rapid
// up; the dwell in seconds (LinuxCNC), in ms (Fanuc), as G4 (grbl, romi).
TEST(BoreCycle, G89AsEachControlWritesIt) {
  const canon::Toolpath tp = bored(kDwellBore);
  const std::string ngc = posted(tp, "rs274ngc");
  EXPECT_NE(ngc.find("G99 G89 X25 Y30 Z-9 R1 P0.5 F"), std::string::npos) << ngc;
  EXPECT_NE(ngc.find("G80\nG0 Z5\nG89 X75 Y30 Z-9 R1 P0.5\nG80\nG0 Z5\n"), std::string::npos)
      << ngc;
  const std::string fanuc = posted(tp, "fanuc");
  EXPECT_NE(fanuc.find("G99 G89 X25. Y30. Z-9. R1. P500 F"), std::string::npos) << fanuc;
  const std::string grbl = posted(tp, "grbl");
  EXPECT_NE(grbl.find("G1 Z-9 F"), std::string::npos) << grbl;
  EXPECT_NE(grbl.find("G4 P0.5\nZ1\nG0 Z5\n"), std::string::npos) << grbl;
  // romi's only dwell is G81's D (out at rapid): the post refuses the bore.
  core::DiagnosticList d;
  test::post_text(tp.ops(), "romi", d);
  const core::Diagnostic* e = find(d, Code::Unsupported);
  ASSERT_NE(e, nullptr);
  EXPECT_NE(e->message.find("a bore's dwell"), std::string::npos) << e->message;
}

// G86: no dwell on a Fanuc, P0 where LinuxCNC wants a P; the moves stop
// the spindle, rapid out and start it again.
TEST(BoreCycle, G86AsEachControlWritesIt) {
  const canon::Toolpath tp = bored(kStopBore);
  EXPECT_NE(posted(tp, "rs274ngc").find("G86 X25 Y30 Z-9 R1 P0 F"), std::string::npos);
  const std::string fanuc = posted(tp, "fanuc");
  EXPECT_NE(fanuc.find("G86 X25. Y30. Z-9. R1. F"), std::string::npos) << fanuc;
  EXPECT_EQ(fanuc.find("P0"), std::string::npos) << fanuc;
  const std::string grbl = posted(tp, "grbl");
  EXPECT_NE(grbl.find("G1 Z-9 F"), std::string::npos) << grbl;
  EXPECT_NE(grbl.find("M5\nG0 Z5\nM3\nX75\n"), std::string::npos) << grbl;
}

// The job's path with its bare holes as stats and simulate follow them
// (canon/bare_hole.hpp).
std::vector<canon::Op> expanded(const canon::Toolpath& tp) {
  std::vector<canon::Op> out;
  core::Vec3 at;
  canon::Feed feed;
  canon::Spindle spindle;
  for (const canon::Op& op : tp.ops()) {
    if (const auto* h = std::get_if<canon::Hole>(&op.kind)) {
      for (const canon::Op& m : canon::bare_hole_moves(op, *h, at, {}, feed, spindle))
        out.push_back(m);
      at = test::motion_ends(out, 1e-9).back();
      continue;
    }
    if (const auto* s = std::get_if<canon::Spindle>(&op.kind)) spindle = *s;
    if (const auto* f = std::get_if<canon::Feed>(&op.kind)) feed = *f;
    out.push_back(op);
    if (canon::is_motion(op.kind)) at = test::motion_ends(out, 1e-9).back();
  }
  return out;
}

struct Seen {
  std::vector<double> dwells;
  int stops_at_bottom = 0;  // spindle stopped with the tool at Z-9
};

Seen seen(const std::vector<canon::Op>& ops) {
  Seen s;
  double z = 0;
  for (const canon::Op& op : ops) {
    if (const auto* d = std::get_if<canon::Dwell>(&op.kind); d && d->s > 0)
      s.dwells.push_back(d->s);
    if (const auto* sp = std::get_if<canon::Spindle>(&op.kind);
        sp && sp->dir == canon::SpindleDir::Off && std::abs(z + 9.0) < 1e-3)
      ++s.stops_at_bottom;
    if (canon::is_motion(op.kind)) z = test::motion_ends({op}, 1e-9).back().z;
  }
  return s;
}

// Every control's program reads back to the path the job's holes stand for
// (the moves stats and simulate follow), with its dwells and spindle stops.
TEST(BoreCycle, G89AndG86ReadBackTheSameInEveryControl) {
  for (const std::string& ops : {kDwellBore, kStopBore}) {
    const canon::Toolpath tp = bored(ops);
    const std::vector<canon::Op> path = expanded(tp);
    const Seen want = seen(path);
    EXPECT_EQ(want.dwells.size() + static_cast<std::size_t>(want.stops_at_bottom), 2u);
    for (const char* post : {"rs274ngc", "fanuc", "grbl", "romi"}) {
      SCOPED_TRACE(post);
      if (ops == kDwellBore && std::string_view(post) == "romi") continue;  // refused, above
      const auto back = test::interpret_in(posted(tp, post), post);
      ASSERT_TRUE(back);
      test::expect_same_path(path, *back, 1e-3);
      const Seen got = seen(*back);
      EXPECT_EQ(got.dwells, want.dwells);
      EXPECT_EQ(got.stops_at_bottom, want.stops_at_bottom);
    }
  }
}

TEST(BorePost, TheTraceSaysHowAHoleIsBored) {
  canon::Hole h{{1, 2, 1}, 10, 10, canon::HoleCycle::BoreDwell};
  h.dwell = 0.5;
  EXPECT_NE(traced(h).find("bored with a dwell 0.5 s"), std::string::npos) << traced(h);
  h.cycle = canon::HoleCycle::BoreStop;
  EXPECT_NE(traced(h).find("bored, spindle stopped"), std::string::npos) << traced(h);
}

}  // namespace
}  // namespace usina::job
