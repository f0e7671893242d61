// The stock route (web_stock.hpp): a revision simulated on a stock, frame
// by frame, against a real server; its final frame against `usina
// simulate`'s report of the same program on the same stock; the query's
// bounds (400 with the reason, 413 before anything is allocated).
#include "dnc/web_stock.hpp"

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "server_fixture.hpp"

namespace usina::dnc {
namespace {

namespace fs = std::filesystem;

// A 6 mm slot (the default tool: the program names no diameter) 2 mm deep
// from X10 Y20 to X50, then up to Y30.
constexpr const char* kSlot =
    "G21 G90 G94\nT1 M6\nG0 X10 Y20 Z5\nG1 Z-2 F300\nG1 X50 F600\nG1 Y30\nG1 X10\nG0 Z5\nM2\n";

struct Decoded {
  nlohmann::json header;
  std::string data;
};

template <class T>
T read(const std::string& s, std::size_t at) {
  T v{};
  std::memcpy(&v, s.data() + at, sizeof v);
  return v;
}

Decoded decode(const std::string& body) {
  EXPECT_TRUE(is_stock_answer(body));
  EXPECT_EQ(read<std::uint32_t>(body, 4), kStockVersion);
  const auto length = read<std::uint32_t>(body, 8);
  return {nlohmann::json::parse(body.substr(12, length)), body.substr(12 + length)};
}

// The depths below the top after frame `upto` (0: the first), the uncut
// stock with every frame's changes laid on.
std::vector<std::uint16_t> depths_after(const Decoded& d, std::size_t upto) {
  const std::size_t cells =
      d.header["cells"][0].get<std::size_t>() * d.header["cells"][1].get<std::size_t>();
  std::vector<std::uint16_t> depth(cells, 0);
  for (std::size_t f = 0; f <= upto; ++f) {
    const auto& frame = d.header["frames"][f];
    const auto runs = frame["runs"].get<std::size_t>();
    const auto changed = frame["cells"].get<std::size_t>();
    const auto at = frame["offset"].get<std::size_t>();
    std::size_t k = 0;
    for (std::size_t r = 0; r < runs; ++r) {
      const auto first = read<std::uint32_t>(d.data, at + 8 * r);
      const auto count = read<std::uint32_t>(d.data, at + 8 * r + 4);
      for (std::uint32_t i = 0; i < count; ++i, ++k)
        depth.at(first + i) = read<std::uint16_t>(d.data, at + 8 * runs + 2 * k);
    }
    EXPECT_EQ(k, changed);
  }
  return depth;
}

double volume_of(const Decoded& d, const std::vector<std::uint16_t>& depth) {
  double sum = 0.0;
  for (const std::uint16_t q : depth)
    sum += q;
  return sum * d.header["depth_unit_mm"].get<double>() * d.header["cell_mm"][0].get<double>() *
         d.header["cell_mm"][1].get<double>();
}

// `usina simulate`'s removed volume of `program` on `stock`.
double simulated_volume(const std::string& program, const std::string& args) {
  const fs::path dir =
      fs::temp_directory_path() / ("usina-web-stock-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "slot.ngc") << program;
  const std::string cmd = std::string(USINA_BINARY) + " simulate " + (dir / "slot.ngc").string() +
                          " " + args + " -o " + (dir / "report.json").string() + " >/dev/null";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
  std::ifstream in(dir / "report.json");
  const auto report = nlohmann::json::parse(in, nullptr, false);
  fs::remove_all(dir);
  return report.value("removed_mm3", -1.0);
}

class WebStockRoute : public ::testing::Test {
 protected:
  void SetUp() override {
    server.start();
    token = client().log_in("prog", test::kPassword);
    const test::Reply up = client().post("/api/programs", {{"name", "O9"}, {"text", kSlot}}, token);
    ASSERT_EQ(up.status, 201) << up.body;
    route = "/api/programs/O9/revisions/" + up.json()["revision"].get<std::string>() + "/stock";
  }

  test::ApiClient client() const { return server.client(); }

  test::Reply get(const std::string& query) const { return client().get(route + query, token); }

  std::uint64_t computed() {
    return server.on_loop([&] { return server.server().toolpaths().counters().computed; });
  }

  test::RunningServer server;
  std::string token;
  std::string route;
};

TEST_F(WebStockRoute, TheFinalFrameRemovesWhatUsinaSimulateRemoves) {
  const test::Reply r = get("?stock=box:60x40x10&origin=0,0,0&resolution=0.25&frames=4");
  ASSERT_EQ(r.status, 200) << r.body;
  const Decoded d = decode(r.body);
  ASSERT_EQ(d.header["frames"].size(), 4u);
  EXPECT_EQ(d.header["cells"][0], 240);
  EXPECT_EQ(d.header["cells"][1], 160);
  const double cli = simulated_volume(kSlot, "--stock box:60x40x10 --resolution 0.25");
  const double cell = 0.25 * 0.25 * 10.0;  // one cell's column
  const auto& last = d.header["frames"].back();
  EXPECT_NEAR(last["removed_mm3"].get<double>(), cli, cell);
  EXPECT_NEAR(d.header["removed_mm3"].get<double>(), cli, cell);
  // The frames laid on the uncut stock are the final map, to a cell.
  EXPECT_NEAR(volume_of(d, depths_after(d, 3)), cli, cell);
  // Three 6 mm slots 2 mm deep, 40 + 10 + 40 mm long, joined: two strips of
  // 40 x 6, the 6 x 10 between less its two 3 x 3 overlaps, a half disc at
  // each open end and a quarter at each outer corner; within a few cells.
  EXPECT_NEAR(cli, 2.0 * (240.0 + 240.0 + 42.0 + 13.5 * 3.14159265), 40.0 * cell);
  EXPECT_EQ(last["moves"], d.header["moves"]);
  EXPECT_TRUE(d.header["complete"]);
}

TEST_F(WebStockRoute, FramesAreEqualSharesOfTheMovesAndTheirStockShrinks) {
  const test::Reply r = get("?stock=box:60x40x10&resolution=0.5&frames=3");
  ASSERT_EQ(r.status, 200) << r.body;
  const Decoded d = decode(r.body);
  const auto& frames = d.header["frames"];
  ASSERT_EQ(frames.size(), 3u);
  // Six moves: after 2, 4 and 6; the plunge is line 4, the first cut line 5.
  EXPECT_EQ(d.header["moves"], 6);
  EXPECT_EQ(frames[0]["moves"], 2);
  EXPECT_EQ(frames[0]["line"], 4);
  EXPECT_EQ(frames[1]["moves"], 4);
  EXPECT_EQ(frames[2]["moves"], 6);
  double before = -1.0;
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const double v = volume_of(d, depths_after(d, f));
    EXPECT_GT(v, before) << f;
    EXPECT_NEAR(v, frames[f]["removed_mm3"].get<double>(), 0.5 * 0.5 * 10.0) << f;
    before = v;
  }
}

// Each frame is stamped with the time the planner of `usina stats` (the
// generic mill) has run its moves: the last is the program's whole time.
TEST_F(WebStockRoute, FramesCarryThePlannersTime) {
  const test::Reply r = get("?stock=box:60x40x10&resolution=0.5&frames=3");
  ASSERT_EQ(r.status, 200) << r.body;
  const Decoded d = decode(r.body);
  const auto& frames = d.header["frames"];
  ASSERT_EQ(frames.size(), 3u);
  const fs::path dir = fs::temp_directory_path() / ("usina-web-time-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "slot.ngc") << kSlot;
  const std::string cmd = std::string(USINA_BINARY) + " stats --format json " +
                          (dir / "slot.ngc").string() + " > " + (dir / "stats.json").string();
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  std::ifstream in(dir / "stats.json");
  const auto stats = nlohmann::json::parse(in, nullptr, false);
  fs::remove_all(dir);
  const double total = stats["time"]["total_s"].get<double>();
  EXPECT_NEAR(d.header["time_s"].get<double>(), total, 1e-9);
  EXPECT_NEAR(frames[2]["time_s"].get<double>(), total, 1e-9);
  // Later frames, later times: the first two slots' moves take seconds.
  EXPECT_GT(frames[0]["time_s"].get<double>(), 0.0);
  EXPECT_GT(frames[1]["time_s"].get<double>(), frames[0]["time_s"].get<double>() + 1.0);
  EXPECT_GT(frames[2]["time_s"].get<double>(), frames[1]["time_s"].get<double>());
  ASSERT_TRUE(d.header["peak_removal"].is_object());
  EXPECT_GT(d.header["peak_removal"]["mm3_per_min"].get<double>(), 0.0);
}

TEST_F(WebStockRoute, WithoutAStockTheProgramsOwnBoxIsCut) {
  const test::Reply r = get("");
  ASSERT_EQ(r.status, 200) << r.body;
  const Decoded d = decode(r.body);
  EXPECT_TRUE(d.header["stock"]["from_program"]);
  // X10..50, Y20..30 grown by the 3 mm radius; top Z0, down to Z-2 and 1 mm more.
  EXPECT_EQ(d.header["stock"]["box"], nlohmann::json({46.0, 16.0, 3.0}));
  EXPECT_EQ(d.header["stock"]["origin"], nlohmann::json({7.0, 17.0, 0.0}));
  EXPECT_EQ(d.header["frames"].size(), 6u);  // 16 asked by default, 6 moves
  EXPECT_EQ(d.header["tools"][0]["tool"], 1);
}

TEST_F(WebStockRoute, AToolOfTheQueryCuts) {
  const test::Reply r = get("?stock=box:60x40x10&resolution=0.5&frames=1&tools=1=flat/10");
  ASSERT_EQ(r.status, 200) << r.body;
  const Decoded d = decode(r.body);
  EXPECT_EQ(d.header["tools"][0]["diameter_mm"], 10.0);
  const double cli = simulated_volume(kSlot,
                                      "--stock box:60x40x10 --resolution 0.5 "
                                      "--tool-shape 1=flat/10");
  EXPECT_NEAR(d.header["removed_mm3"].get<double>(), cli, 0.5 * 0.5 * 10.0);
}

TEST_F(WebStockRoute, MalformedValuesAre400WithTheReason) {
  const std::pair<const char*, const char*> bad[] = {
      {"?frames=0", "frames"},
      {"?frames=65", "frames"},
      {"?frames=two", "frames"},
      {"?resolution=0", "resolution"},
      {"?resolution=fine", "resolution"},
      {"?stock=cube:10", "box:WxLxH"},
      {"?stock=box:10x10", "box:WxLxH"},
      {"?stock=box:10x10x-1", "sides"},
      {"?stock=box:20000x10x10", "sides"},
      {"?origin=0,0,0", "origin"},
      {"?stock=box:10x10x10&origin=1,2", "origin"},
      {"?tools=1=blob/6", "tools"},
      {"?colour=red", "colour"},
  };
  for (const auto& [query, word] : bad) {
    const test::Reply r = get(query);
    EXPECT_EQ(r.status, 400) << query << ": " << r.body;
    EXPECT_NE(r.json().value("error", "").find(word), std::string::npos) << query << r.body;
  }
  EXPECT_EQ(computed(), 0u);
}

TEST_F(WebStockRoute, TooManyCellsOrFramesAre413BeforeAnythingRuns) {
  const test::Reply cells = get("?stock=box:10000x10000x10&resolution=0.01");
  EXPECT_EQ(cells.status, 413) << cells.body;
  EXPECT_NE(cells.json().value("error", "").find("cells"), std::string::npos) << cells.body;
  // 2000 x 2000 cells of 1 mm are allowed, but not 64 frames of them.
  const test::Reply frames = get("?stock=box:2000x2000x10&resolution=1&frames=64");
  EXPECT_EQ(frames.status, 413) << frames.body;
  EXPECT_NE(frames.json().value("error", "").find("fewer frames (at most 8)"), std::string::npos)
      << frames.body;
  EXPECT_EQ(computed(), 0u);
  EXPECT_EQ(get("?stock=box:60x40x10&frames=2").status, 200);
}

TEST_F(WebStockRoute, ComputedOnceThenFromTheCache) {
  const test::Reply first = get("?frames=2");
  ASSERT_EQ(first.status, 200);
  const test::Reply second = get("?frames=2");
  EXPECT_EQ(second.body, first.body);
  EXPECT_EQ(computed(), 1u);
  EXPECT_EQ(get("?frames=3").status, 200);  // other settings, another run
  EXPECT_EQ(computed(), 2u);
  EXPECT_EQ(client().get(route).status, 401);
  EXPECT_EQ(
      client().get("/api/programs/O9/revisions/" + std::string(64, 'a') + "/stock", token).status,
      404);
}

TEST_F(WebStockRoute, AProgramTooWideForItsOwnStockIs422WithTheReason) {
  const test::Reply up = client().post(
      "/api/programs",
      {{"name", "O10"}, {"text", "G21 G90\nG0 X0 Y0 Z1\nG1 Z-1 F100\nG1 X20000\nM2\n"}}, token);
  ASSERT_EQ(up.status, 201) << up.body;
  const std::string wide =
      "/api/programs/O10/revisions/" + up.json()["revision"].get<std::string>() + "/stock";
  const test::Reply r = client().get(wide, token);
  EXPECT_EQ(r.status, 422) << r.body;
  EXPECT_NE(r.json().value("error", "").find("give stock=box"), std::string::npos) << r.body;
  EXPECT_EQ(client().get(wide, token).status, 422);  // the refusal kept, as answers are
  EXPECT_EQ(client().get(wide + "?stock=box:100x20x5&origin=-10,-10,0", token).status, 200);
}

TEST(WebStock, AResolutionWithoutAStockIsMadeCoarserToFit) {
  StockSettings s;
  s.resolution = 0.001;  // 46 x 16 mm: 736 million cells
  s.frames = 2;
  const std::string bytes = encode_stock(kSlot, s);
  const Decoded d = decode(bytes);
  const auto cells =
      d.header["cells"][0].get<std::uint64_t>() * d.header["cells"][1].get<std::uint64_t>();
  EXPECT_LE(cells, s.limits.max_cells);
  EXPECT_GT(cells, s.limits.max_cells * 9 / 10);
}

TEST(WebStock, AProgramTooWideForItsOwnStockIsRefusedWithTheReason) {
  StockSettings s;
  const std::string bytes = encode_stock("G21 G90\nG0 X0 Y0 Z1\nG1 Z-1 F100\nG1 X20000\nM2\n", s);
  EXPECT_FALSE(is_stock_answer(bytes));
  const auto why = nlohmann::json::parse(bytes);
  EXPECT_NE(why["error"].get<std::string>().find("give stock=box"), std::string::npos) << bytes;
}

TEST(WebStock, AProgramThatCutsNothingHasASmallBlockAtItsZero) {
  StockSettings s;
  const Decoded d = decode(encode_stock("G21 G90\nG0 X5 Y5 Z5\nM2\n", s));
  EXPECT_EQ(d.header["stock"]["box"], nlohmann::json({10.0, 10.0, 1.0}));
  EXPECT_EQ(d.header["removed_mm3"], 0.0);
  EXPECT_EQ(d.header["frames"].size(), 1u);
}

TEST(WebStock, FramesPastTheAnswersBoundAreRefusedWith413) {
  StockSettings s;
  s.box = sim::stock::StockBox{60.0, 40.0, 10.0, {}};
  s.resolution = 0.5;
  s.frames = 6;
  s.limits.max_answer_bytes = 2000;  // the slot's first frames are more
  const std::string bytes = encode_stock(kSlot, s);
  ASSERT_FALSE(is_stock_answer(bytes));
  const auto why = nlohmann::json::parse(bytes);
  EXPECT_EQ(why["status"], 413);
  EXPECT_NE(why["error"].get<std::string>().find("2000 bytes"), std::string::npos) << bytes;
  s.limits.max_answer_bytes = 1u << 20;
  EXPECT_TRUE(is_stock_answer(encode_stock(kSlot, s)));
}

TEST(WebStock, ACutShallowerThanHalfADepthUnitChangesNoCell) {
  StockSettings s;
  s.box = sim::stock::StockBox{30.0, 30.0, 5.0, {-5.0, -5.0, 0.0}};
  s.resolution = 0.5;
  s.frames = 1;
  // 10 nm deep: a profile at the top's Z, lowered by rounding; the unit is 76 µm.
  const Decoded d =
      decode(encode_stock("G21 G90\nG0 X0 Y0 Z1\nG1 Z-0.00001 F100\nG1 X20\nM2\n", s));
  EXPECT_GT(d.header["removed_mm3"].get<double>(), 0.0);
  EXPECT_EQ(d.header["frames"][0]["cells"], 0);
}

}  // namespace
}  // namespace usina::dnc
