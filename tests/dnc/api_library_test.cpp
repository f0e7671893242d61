// GET /api/programs as a page of the library: its filters and count over
// HTTP, and every malformed query answered 400 with what is wrong.
#include <gtest/gtest.h>

#include "server_fixture.hpp"

namespace usina::dnc {
namespace {

using test::ApiClient;
using test::RunningServer;

nlohmann::json upload(const std::string& name, const std::string& machine_class,
                      const std::string& text) {
  return {{"name", name},
          {"machine_class", machine_class},
          {"dialect", "rs274ngc"},
          {"text", text},
          {"reason", "test"}};
}

TEST(ApiLibrary, APageOfProgramsWithTheirNewestStateAndTheCount) {
  RunningServer s;
  s.start();
  const ApiClient c = s.client();
  const std::string prog = c.log_in("prog", test::kPassword);
  for (int i = 0; i < 12; ++i) {
    const std::string name = "O" + std::to_string(1000 + i);
    const std::string text = "(" + name + ")\nG21 G90\nG0 X1 Y1\nM2\n";
    ASSERT_EQ(c.post("/api/programs", upload(name, i < 3 ? "lathe" : "mill", text), prog).status,
              201);
  }
  const auto all = c.get("/api/programs", prog).json();
  EXPECT_EQ(all["total"], 12);
  EXPECT_EQ(all["programs"].size(), 12u);
  EXPECT_EQ(all["programs"][0]["newest_state"], "draft");
  EXPECT_TRUE(all["programs"][0]["released_revision"].is_null());
  const auto page = c.get("/api/programs?machine_class=mill&limit=4&offset=8", prog).json();
  EXPECT_EQ(page["total"], 9);
  ASSERT_EQ(page["programs"].size(), 1u);
  EXPECT_EQ(page["programs"][0]["name"], "O1011");
  const auto found = c.get("/api/programs?q=o100&state=draft", prog).json();
  EXPECT_EQ(found["total"], 10);  // O1000 to O1009
  EXPECT_EQ(c.get("/api/programs?released=1", prog).json()["total"], 0);
}

TEST(ApiLibrary, MalformedQueriesAreRefusedWithTheReason) {
  RunningServer s;
  s.start();
  const ApiClient c = s.client();
  const std::string prog = c.log_in("prog", test::kPassword);
  const std::pair<const char*, const char*> bad[] = {
      {"state=finished", "state must be"},
      {"limit=0", "limit must be a whole number from 1 to 10000"},
      {"limit=10001", "limit must be"},
      {"limit=5x", "limit must be"},
      {"offset=-1", "offset must be"},
      {"released=yes", "released must be 1 or 0"},
      {"tool=T5", "tool must be a whole number from 0 to 99999999"},
      {"tool=-1", "tool must be"},
      {"tool=1.5", "tool must be"},
      {"tool=100000000", "tool must be"},
      {"text=%FF", "text is not UTF-8"},
  };
  for (const auto& [query, why] : bad) {
    const test::Reply r = c.get(std::string("/api/programs?") + query, prog);
    EXPECT_EQ(r.status, 400) << query;
    EXPECT_NE(r.body.find(why), std::string::npos) << query << ": " << r.body;
  }
  const test::Reply long_q = c.get("/api/programs?q=" + std::string(201, 'a'), prog);
  EXPECT_EQ(long_q.status, 400);
  EXPECT_NE(long_q.body.find("q is longer than 200 bytes"), std::string::npos) << long_q.body;
  const test::Reply long_text = c.get("/api/programs?text=" + std::string(201, 'a'), prog);
  EXPECT_EQ(long_text.status, 400);
  EXPECT_NE(long_text.body.find("text is longer than 200 bytes"), std::string::npos)
      << long_text.body;
}

TEST(ApiLibrary, TextAndToolSearchTheNewestRevisionsCommentsNumbersAndTools) {
  RunningServer s;
  s.start();
  const ApiClient c = s.client();
  const std::string prog = c.log_in("prog", test::kPassword);
  const std::pair<const char*, const char*> programs[] = {
      {"BRACKET", "%\nO4711 (BRACKET FOR PUMP)\nT5 M6\nG0 X1 Y1\nM2\n%\n"},
      {"FLANGE", "(six holes)\nT12 M6\nG0 X1 Y1\nM2\n"},
      {"PUMP_COVER", "(lid)\nT5 M6\nG0 X1 Y1\nM2\n"},
  };
  for (const auto& [name, text] : programs)
    ASSERT_EQ(c.post("/api/programs", upload(name, "mill", text), prog).status, 201) << name;
  const auto names = [&](const std::string& query) {
    const test::Reply r = c.get("/api/programs?" + query, prog);
    EXPECT_EQ(r.status, 200) << query << ": " << r.body;
    const nlohmann::json page = r.json();
    std::vector<std::string> out;
    for (const auto& p : page["programs"])
      out.push_back(p["name"]);
    return out;
  };
  using Names = std::vector<std::string>;
  EXPECT_EQ(names("text=pump"), (Names{"BRACKET", "PUMP_COVER"}));  // a comment, a name
  EXPECT_EQ(names("q=pump"), Names{"PUMP_COVER"});                  // q stays the name
  EXPECT_EQ(names("text=O4711"), Names{"BRACKET"});
  EXPECT_EQ(names("text=SIX%20HOLES"), Names{"FLANGE"});
  EXPECT_EQ(names("tool=5"), (Names{"BRACKET", "PUMP_COVER"}));
  EXPECT_EQ(names("tool=12"), Names{"FLANGE"});
  EXPECT_EQ(names("tool=5&text=lid"), Names{"PUMP_COVER"});
  EXPECT_EQ(names("tool="), (Names{"BRACKET", "FLANGE", "PUMP_COVER"}));  // empty: any
  const auto page = c.get("/api/programs?tool=5&limit=1&offset=1", prog).json();
  EXPECT_EQ(page["total"], 2);
  EXPECT_EQ(page["programs"][0]["name"], "PUMP_COVER");
  EXPECT_EQ(page["machine_classes"], nlohmann::json::array({"mill"}));
}

}  // namespace
}  // namespace usina::dnc
