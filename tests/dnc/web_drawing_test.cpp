// The 2D drawing of a revision (web_drawing.hpp) and its route: the SVG or
// DXF of usina draw made in memory, bounded, its refusals, and the answer
// computed once on the tool-path service's pool, then served from its cache.
#include "dnc/web_drawing.hpp"

#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "server_fixture.hpp"

namespace usina::dnc {
namespace {

std::string seed_000() {
  std::ifstream in(std::string(USINA_TEST_DIR) + "/programs/romi/seed-000-example.nc");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

DrawingSettings romi(DrawingFormat format = DrawingFormat::Svg) {
  DrawingSettings s;
  s.dialect = "romi";
  s.format = format;
  return s;
}

constexpr const char* kTwoTools =
    "G21 G90 G94\nT1 M6\nG0 X0 Y0 Z1\nG1 Z-1 F100\nG1 X100 F1000\nT2 M6\nG1 Y50 F500\nG0 Z10\nM2\n";

TEST(WebDrawing, SeedZerosPartViewHoldsItsFourLayers) {
  const DrawingAnswer a = program_drawing(seed_000(), romi());
  ASSERT_EQ(a.status, 200u) << a.note;
  EXPECT_TRUE(a.complete) << a.note;
  EXPECT_EQ(a.body.rfind("<?xml", 0), 0u);
  for (const char* layer : {"CONTOUR", "RAPID", "HOLES", "POCKETS"})
    EXPECT_NE(a.body.find(std::string("<g id=\"") + layer + "\""), std::string::npos) << layer;
}

TEST(WebDrawing, SeedZerosDxfHasTheLayersInItsTable) {
  const DrawingAnswer a = program_drawing(seed_000(), romi(DrawingFormat::Dxf));
  ASSERT_EQ(a.status, 200u) << a.note;
  EXPECT_NE(a.body.find("SECTION"), std::string::npos);
  EXPECT_NE(a.body.find("\nCONTOUR"), std::string::npos);
  EXPECT_NE(a.body.find("\nHOLES"), std::string::npos);
  EXPECT_EQ(a.body.find("<svg"), std::string::npos);
}

TEST(WebDrawing, TheToolpathViewHasALayerPerTool) {
  DrawingSettings s;
  s.view = draw::View::Toolpath;
  const DrawingAnswer a = program_drawing(kTwoTools, s);
  ASSERT_EQ(a.status, 200u) << a.note;
  EXPECT_NE(a.body.find("<g id=\"TOOLPATH_T1\""), std::string::npos);
  EXPECT_NE(a.body.find("<g id=\"TOOLPATH_T2\""), std::string::npos);
  EXPECT_EQ(a.body.find("<g id=\"CONTOUR\""), std::string::npos);
}

TEST(WebDrawing, AProgramStoppedByAnErrorIsDrawnUpToItWithANote) {
  const DrawingAnswer a =
      program_drawing("G0 X0 Y0 Z0\nG1 X20 F100\nG999\nG1 X20 Y70\nM2\n", DrawingSettings{});
  ASSERT_EQ(a.status, 200u) << a.note;
  EXPECT_FALSE(a.complete);
  EXPECT_NE(a.note.find("stops at line 3"), std::string::npos) << a.note;
  EXPECT_NE(a.note.find("the drawing shows what ran before"), std::string::npos) << a.note;
  EXPECT_NE(a.body.find("x2=\"20\""), std::string::npos) << a.body;
  // The move to Y70 after the error is not drawn: the picture is 20 mm wide, flat.
  EXPECT_EQ(a.body.find("70"), std::string::npos) << a.body;
}

TEST(WebDrawing, AnErrorBeforeAnyMoveIs422WithItsLine) {
  const DrawingAnswer a = program_drawing("G999\nG1 X20 F100\n", DrawingSettings{});
  EXPECT_EQ(a.status, 422u);
  EXPECT_EQ(a.note.rfind("nothing to draw: the program stops at line 1 (", 0), 0u) << a.note;
  EXPECT_NE(a.note.find("before its first move"), std::string::npos) << a.note;
  EXPECT_TRUE(a.body.empty());
}

TEST(WebDrawing, AnUnknownDialectIs422) {
  DrawingSettings s;
  s.dialect = "no-such-control";
  const DrawingAnswer a = program_drawing(kTwoTools, s);
  EXPECT_EQ(a.status, 422u);
  EXPECT_NE(a.note.find("no-such-control"), std::string::npos) << a.note;
}

// A zigzag of 200 lines, none merging with the next.
std::string zigzag() {
  std::string text = "G0 X0 Y0 Z0\n";
  for (int i = 1; i <= 200; ++i)
    text += "G1 X" + std::to_string(i) + " Y" + std::to_string(i % 2 * 10) + " F100\n";
  return text + "M2\n";
}

TEST(WebDrawing, MovesPastTheEntityBoundAreLeftOutAndCounted) {
  DrawingSettings s;
  s.max_entities = 50;
  const DrawingAnswer a = program_drawing(zigzag(), s);
  ASSERT_EQ(a.status, 200u) << a.note;
  EXPECT_FALSE(a.complete);
  EXPECT_NE(a.note.find("on are not drawn (the 3D viewer shows every move)"), std::string::npos)
      << a.note;
  // Advice for the page's reader, not for a command line.
  EXPECT_NE(a.note.find("3D viewer"), std::string::npos) << a.note;
  EXPECT_EQ(a.note.find("usina "), std::string::npos) << a.note;
  const DrawingAnswer whole = program_drawing(zigzag(), DrawingSettings{});
  EXPECT_TRUE(whole.complete) << whole.note;
  EXPECT_GT(whole.body.size(), 2 * a.body.size());
}

TEST(WebDrawing, ADrawingPastTheByteBoundIs413) {
  DrawingSettings s;
  s.max_bytes = 1000;
  const DrawingAnswer a = program_drawing(zigzag(), s);
  EXPECT_EQ(a.status, 413u);
  EXPECT_NE(a.note.find("more than the 1000"), std::string::npos) << a.note;
  EXPECT_NE(a.note.find("the 3D viewer shows every move"), std::string::npos) << a.note;
  EXPECT_TRUE(a.body.empty());
}

TEST(WebDrawing, TheAnswerComesBackFromItsEncoding) {
  DrawingAnswer a;
  a.complete = false;
  a.note = "line 3: a dash \u2013 and a\nnew line";
  a.body = "<svg>\n</svg>\n";
  const std::string bytes = encode_drawing_answer(a);
  EXPECT_LT(bytes.find('\n'), bytes.find("<svg>"));
  const auto back = decode_drawing_answer(bytes);
  ASSERT_TRUE(back);
  EXPECT_EQ(back->status, 200u);
  EXPECT_FALSE(back->complete);
  EXPECT_EQ(back->note, a.note);
  EXPECT_EQ(back->body, a.body);
  EXPECT_FALSE(decode_drawing_answer("<svg/>"));
  EXPECT_FALSE(decode_drawing_answer("[1]\n<svg/>"));
}

// The route, against a real server.
class WebDrawingRoute : public ::testing::Test {
 protected:
  void SetUp() override {
    server_.start();
    prog_ = client().log_in("prog", test::kPassword);
    oper_ = client().log_in("oper", test::kPassword);
  }

  test::ApiClient client() const { return server_.client(); }

  // The revision of an upload of `text`.
  std::string upload(const std::string& name, const std::string& text,
                     const std::string& dialect = "rs274ngc") {
    const test::Reply up = client().post(
        "/api/programs", {{"name", name}, {"text", text}, {"dialect", dialect}}, prog_);
    EXPECT_TRUE(up.status == 201 || up.status == 200) << up.body;
    return up.json().value("revision", "");
  }

  test::Reply drawing(const std::string& name, const std::string& rev,
                      const std::string& query = "") {
    return client().get("/api/programs/" + name + "/revisions/" + rev + "/drawing" + query, oper_);
  }

  test::RunningServer server_;
  std::string prog_;
  std::string oper_;
};

TEST_F(WebDrawingRoute, SeedZeroIsAnSvgOfItsLayersThenFromTheCache) {
  const std::string rev = upload("seed-000", seed_000(), "romi");
  const test::Reply first = drawing("seed-000", rev);
  ASSERT_EQ(first.status, 200) << first.body;
  EXPECT_EQ(first.header("content-type"), "image/svg+xml");
  EXPECT_EQ(first.header("x-drawing-complete"), "true");
  EXPECT_EQ(first.header("content-security-policy"), "default-src 'none'");
  EXPECT_EQ(first.header("content-disposition"),
            "inline; filename=\"seed-000-" + rev.substr(0, 12) + ".svg\"");
  for (const char* layer : {"CONTOUR", "RAPID", "HOLES", "POCKETS"})
    EXPECT_NE(first.body.find(std::string("<g id=\"") + layer + "\""), std::string::npos) << layer;
  EXPECT_EQ(first.header("x-toolpath-cache"), "computed");
  const test::Reply again = drawing("seed-000", rev, "?view=part&format=svg");
  EXPECT_EQ(again.body, first.body);
  EXPECT_EQ(again.header("x-toolpath-cache"), "hit");
  const ToolpathCounters n =
      server_.on_loop([&] { return server_.server().toolpaths().counters(); });
  EXPECT_EQ(n.computed, 1u);
  EXPECT_EQ(n.hits, 1u);
}

TEST_F(WebDrawingRoute, DxfIsADownloadAndTheToolpathViewAnotherDrawing) {
  const std::string rev = upload("O7", kTwoTools);
  const test::Reply dxf = drawing("O7", rev, "?format=dxf");
  ASSERT_EQ(dxf.status, 200) << dxf.body;
  EXPECT_EQ(dxf.header("content-type"), "image/vnd.dxf");
  EXPECT_EQ(dxf.header("content-disposition"),
            "attachment; filename=\"O7-" + rev.substr(0, 12) + ".dxf\"");
  EXPECT_NE(dxf.body.find("SECTION"), std::string::npos);
  const test::Reply path = drawing("O7", rev, "?view=toolpath");
  ASSERT_EQ(path.status, 200) << path.body;
  EXPECT_NE(path.body.find("<g id=\"TOOLPATH_T2\""), std::string::npos);
  const ToolpathCounters n =
      server_.on_loop([&] { return server_.server().toolpaths().counters(); });
  EXPECT_EQ(n.computed, 2u);
}

TEST_F(WebDrawingRoute, ARevisionWithAnErrorIsDrawnUpToItAndSaysSo) {
  const std::string rev = upload("broken", "G0 X0 Y0 Z0\nG1 X20 F100\nG999\nG1 Y70\nM2\n");
  const test::Reply r = drawing("broken", rev);
  ASSERT_EQ(r.status, 200) << r.body;
  EXPECT_EQ(r.header("x-drawing-complete"), "false");
  EXPECT_NE(r.header("x-drawing-note").find("stops at line 3"), std::string::npos)
      << r.header("x-drawing-note");
  const std::string nothing = upload("nothing", "G999\nG1 X20 F100\n");
  const test::Reply refused = drawing("nothing", nothing);
  EXPECT_EQ(refused.status, 422) << refused.body;
  EXPECT_NE(refused.json().value("error", "").find("nothing to draw"), std::string::npos)
      << refused.body;
}

TEST_F(WebDrawingRoute, RefusalsBeforeAnythingRuns) {
  const std::string rev = upload("O7", kTwoTools);
  const test::Reply view = drawing("O7", rev, "?view=side");
  EXPECT_EQ(view.status, 400);
  EXPECT_NE(view.json().value("error", "").find("view must be part"), std::string::npos);
  const test::Reply format = drawing("O7", rev, "?format=png");
  EXPECT_EQ(format.status, 400);
  EXPECT_NE(format.json().value("error", "").find("format must be svg or dxf"), std::string::npos);
  EXPECT_EQ(drawing("O7", std::string(64, 'a')).status, 404);
  EXPECT_EQ(drawing("O8", rev).status, 404);
  EXPECT_EQ(client().get("/api/programs/O7/revisions/" + rev + "/drawing").status, 401);
  const ToolpathCounters n =
      server_.on_loop([&] { return server_.server().toolpaths().counters(); });
  EXPECT_EQ(n.computed, 0u);
}

}  // namespace
}  // namespace usina::dnc
