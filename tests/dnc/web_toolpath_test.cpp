// The viewer's tool-path stream (web_toolpath.hpp, docs/web.md): its bytes,
// arcs linearised, tools and lines carried, and decimation that keeps a
// program of a million moves small; the route's refusals.
#include "dnc/web_toolpath.hpp"

#include <cmath>
#include <cstring>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "dnc/store_check.hpp"
#include "server_fixture.hpp"

namespace usina::dnc {
namespace {

template <class T>
T at(const std::string& bytes, std::size_t offset) {
  T v{};
  EXPECT_LE(offset + sizeof(T), bytes.size());
  if (offset + sizeof(T) <= bytes.size()) std::memcpy(&v, bytes.data() + offset, sizeof(T));
  return v;
}

// The offsets of the stream's arrays for `n` vertices.
struct Layout {
  std::size_t positions = kToolpathHeaderBytes;
  std::size_t lines;
  std::size_t tools;
  std::size_t times;
  std::size_t kinds;
  std::size_t size;

  explicit Layout(std::size_t n)
      : lines(positions + 12 * n),
        tools(lines + 4 * n),
        times(tools + 4 * n),
        kinds(times + 4 * n),
        size(kinds + n) {}
};

TEST(WebToolpath, TheStreamHasTheDocumentedBytes) {
  const ToolpathResult r = program_toolpath("G0 X10 Y0 Z5\nG1 X10 Y20 Z-1 F100\n", {});
  ASSERT_TRUE(r.ok);
  const std::string b = encode_toolpath(r);
  const Layout l(3);
  ASSERT_EQ(b.size(), l.size);
  EXPECT_EQ(b.substr(0, 4), "USTP");
  EXPECT_EQ(at<std::uint32_t>(b, 4), 2u);   // version
  EXPECT_EQ(at<std::uint32_t>(b, 8), 3u);   // vertices: the start and two moves
  EXPECT_EQ(at<std::uint32_t>(b, 12), 0u);  // flags: not decimated, complete
  EXPECT_EQ(at<std::uint64_t>(b, 16), 2u);  // moves
  const float bounds[6] = {0, 0, -1, 10, 20, 5};
  for (std::size_t i = 0; i < 6; ++i)
    EXPECT_EQ(at<float>(b, 24 + 4 * i), bounds[i]) << i;
  const float xyz[9] = {0, 0, 0, 10, 0, 5, 10, 20, -1};
  for (std::size_t i = 0; i < 9; ++i)
    EXPECT_EQ(at<float>(b, l.positions + 4 * i), xyz[i]) << i;
  EXPECT_EQ(at<std::uint32_t>(b, l.lines + 4), 1u);
  EXPECT_EQ(at<std::uint32_t>(b, l.lines + 8), 2u);
  EXPECT_EQ(at<std::uint8_t>(b, l.kinds + 0), 0u);  // start
  EXPECT_EQ(at<std::uint8_t>(b, l.kinds + 1), 1u);  // rapid
  EXPECT_EQ(at<std::uint8_t>(b, l.kinds + 2), 2u);  // feed
  // The times: 0 at the start, then when each move ends; the program's
  // time in the header is the last vertex's (nothing waits after it).
  EXPECT_EQ(at<float>(b, l.times), 0.0f);
  const auto rapid_end = at<float>(b, l.times + 4);
  const auto feed_end = at<float>(b, l.times + 8);
  EXPECT_GT(rapid_end, 0.0f);
  // 21.8 mm at 100 mm/min: 13.1 s and a little for the acceleration.
  const double feed_s = std::sqrt(20.0 * 20.0 + 6.0 * 6.0) / (100.0 / 60.0);
  EXPECT_GE(feed_end - rapid_end, feed_s - 1e-3);
  EXPECT_LT(feed_end - rapid_end, feed_s + 1.0);
  EXPECT_NEAR(at<double>(b, 48), feed_end, 1e-4);
}

// The times are stats': the path's last time is the revision check's
// cycle time, a dwell is a step in time between two vertices, and the
// chords of an arc share its time evenly.
TEST(WebToolpath, EachVertexIsTimedAsStatsTimesTheProgram) {
  const std::string text = "G1 X100 F600\nG4 P2\nG2 X0 Y0 I-50 J0\nM2\n";
  const ToolpathResult r = program_toolpath(text, {});
  ASSERT_TRUE(r.ok);
  ASSERT_GT(r.vertices.size(), 10u);
  EXPECT_EQ(r.vertices[0].t, 0.0f);
  for (std::size_t i = 1; i < r.vertices.size(); ++i)
    ASSERT_GE(r.vertices[i].t, r.vertices[i - 1].t) << i;
  const double line_end = r.vertices[1].t;
  EXPECT_GE(line_end, 10.0 - 1e-3);  // 100 mm at 10 mm/s
  EXPECT_LT(line_end, 11.0);
  // The half circle (157 mm, 15.7 s) starts after the dwell.
  const double arc_first = r.vertices[2].t;
  const double per_chord =
      (r.total_s - line_end - 2.0) / static_cast<double>(r.vertices.size() - 2);
  EXPECT_NEAR(arc_first - line_end, 2.0 + per_chord, 1e-3);
  for (std::size_t i = 3; i < r.vertices.size(); ++i)
    EXPECT_NEAR(r.vertices[i].t - r.vertices[i - 1].t, per_chord, 1e-3) << i;
  const CheckResults check = check_program(text, {});
  EXPECT_NEAR(r.total_s, check.cycle_time_s, 1e-9);
  EXPECT_NEAR(r.vertices.back().t, r.total_s, 1e-3);
}

TEST(WebToolpath, TheProfileGivesTheTimes) {
  ToolpathSettings slow;
  slow.profile.axes[0].rapid = 1000.0;  // X, mm/min
  const std::string text = "G0 X500\n";
  const double generic = program_toolpath(text, {}).total_s;
  const double on_slow = program_toolpath(text, slow).total_s;
  EXPECT_GE(on_slow, 30.0);  // 500 mm at 1000 mm/min
  EXPECT_LT(generic, on_slow);
}

TEST(WebToolpath, AnArcIsLinearisedOnItsCircle) {
  const ToolpathResult r = program_toolpath("G0 X10 Y0\nG3 X-10 Y0 I-10 J0 F100\n", {});
  ASSERT_TRUE(r.ok);
  ASSERT_GT(r.vertices.size(), 10u);
  for (std::size_t i = 2; i < r.vertices.size(); ++i) {
    const PathVertex& v = r.vertices[i];
    EXPECT_EQ(v.kind, PathKind::Arc);
    EXPECT_EQ(v.line, 2u);
    EXPECT_NEAR(std::hypot(v.x, v.y), 10.0, 1e-4);
    EXPECT_GE(v.y, -1e-4f);  // counter-clockwise from +X: through +Y
  }
  EXPECT_NEAR(r.vertices.back().x, -10.0f, 1e-5);
}

TEST(WebToolpath, EachVertexCarriesItsTool) {
  const ToolpathResult r = program_toolpath("G0 X1\nT7 M6\nG0 X2\nG1 X3 F100\n", {});
  ASSERT_TRUE(r.ok);
  ASSERT_GE(r.vertices.size(), 3u);
  EXPECT_EQ(r.vertices[1].tool, 0u);  // before the change
  EXPECT_EQ(r.vertices.back().tool, 7u);
  EXPECT_EQ(r.vertices.back().line, 4u);
}

TEST(WebToolpath, AnUnknownDialectIsFlagged) {
  ToolpathSettings s;
  s.dialect = "no-such-control";
  const std::string b = encode_toolpath(program_toolpath("G0 X1\n", s));
  EXPECT_EQ(at<std::uint32_t>(b, 8), 1u);
  EXPECT_EQ(at<std::uint32_t>(b, 12) & 4u, 4u);
}

TEST(WebToolpath, AMillionMovesAreDecimatedToTheBudget) {
  std::vector<PathVertex> path(1'000'001);
  for (std::size_t i = 1; i < path.size(); ++i) {
    const double t = static_cast<double>(i) * 1e-4;  // a spiral of small feeds
    path[i] = {static_cast<float>(std::cos(t) * t),
               static_cast<float>(std::sin(t) * t),
               0.0f,
               PathKind::Feed,
               1,
               static_cast<std::uint32_t>(i)};
  }
  const std::vector<PathVertex> kept = decimate(path, 50'000);
  ASSERT_LE(kept.size(), 50'000u);
  EXPECT_GT(kept.size(), 1'000u);  // still a spiral, not a line
  EXPECT_EQ(kept.front().line, 0u);
  EXPECT_EQ(kept.back().line, 1'000'000u);
  for (std::size_t i = 1; i < kept.size(); ++i)
    ASSERT_GT(kept[i].line, kept[i - 1].line);  // in the program's order
}

TEST(WebToolpath, KindsAlternatingAtEveryMoveAreSampledToTheBudget) {
  std::vector<PathVertex> path(100'000);
  for (std::size_t i = 0; i < path.size(); ++i)
    path[i] = {0.0f,
               0.0f,
               static_cast<float>(i % 2),
               i % 2 ? PathKind::Rapid : PathKind::Feed,
               1,
               static_cast<std::uint32_t>(i)};
  const std::vector<PathVertex> kept = decimate(path, 1'000);
  EXPECT_LE(kept.size(), 1'000u);
  EXPECT_EQ(kept.back().line, 99'999u);
}

TEST(WebToolpath, ASmallPathIsKeptWhole) {
  const std::vector<PathVertex> path(10);
  EXPECT_EQ(decimate(path, 100).size(), 10u);
}

std::string long_program(int blocks) {
  std::string text = "G0 X0 Y0\nG1 F1000\n";
  for (int i = 0; i < blocks; ++i)
    text += fmt::format("X{:.3f} Y{:.3f}\n", std::cos(i * 0.001) * i * 0.01,
                        std::sin(i * 0.001) * i * 0.01);
  return text + "M2\n";
}

TEST(WebToolpath, TheRouteAnswersTheStreamOfARevision) {
  test::RunningServer server;
  server.start();
  const test::ApiClient client = server.client();
  const std::string prog = client.log_in("prog", test::kPassword);
  const test::Reply up =
      client.post("/api/programs", {{"name", "O1"}, {"text", long_program(20'000)}}, prog);
  ASSERT_EQ(up.status, 201) << up.body;
  const std::string rev = up.json()["revision"];
  const std::string oper = client.log_in("oper", test::kPassword);
  const std::string route = "/api/programs/O1/revisions/" + rev + "/toolpath";
  const test::Reply whole = client.get(route, oper);
  ASSERT_EQ(whole.status, 200);
  EXPECT_EQ(whole.body.substr(0, 4), "USTP");
  // G0, then `G1 F1000` (a feed where the tool stands, as LinuxCNC's canon has it), 20,000 feeds.
  EXPECT_EQ(at<std::uint64_t>(whole.body, 16), 20'002u);
  const test::Reply small = client.get(route + "?max_vertices=500", oper);
  ASSERT_EQ(small.status, 200);
  const auto n = at<std::uint32_t>(small.body, 8);
  EXPECT_LE(n, 500u);
  EXPECT_EQ(small.body.size(), Layout(n).size);
  EXPECT_EQ(at<std::uint32_t>(small.body, 12) & 1u, 1u);  // decimated
  EXPECT_EQ(client.get(route).status, 401);
  EXPECT_EQ(client.get(route + "?max_vertices=1", oper).status, 400);
  EXPECT_EQ(client.get(route + "?max_vertices=x", oper).status, 400);
  EXPECT_EQ(client.get(route + "?max_vertices=99999999999", oper).status, 400);
  EXPECT_EQ(
      client.get("/api/programs/O1/revisions/" + std::string(64, 'a') + "/toolpath", oper).status,
      404);
  EXPECT_EQ(client.get("/api/programs/O2/revisions/" + rev + "/toolpath", oper).status, 404);
}

}  // namespace
}  // namespace usina::dnc
