// Programs over HTTP: an upload is a revision addressed by the SHA-256 of
// its bytes, with the store's check; revisions newest first with their
// state; moves by role, illegal ones refused; the diffs; malformed requests.
#include <gtest/gtest.h>

#include "dnc/sha256.hpp"
#include "server_fixture.hpp"

namespace usina::dnc {
namespace {

using test::ApiClient;
using test::RunningServer;

nlohmann::json upload(const std::string& name, const std::string& text) {
  return {{"name", name},
          {"machine_class", "mill"},
          {"dialect", "rs274ngc"},
          {"text", text},
          {"reason", "test"}};
}

int move(const ApiClient& c, const std::string& token, const std::string& name,
         const std::string& rev, const std::string& state) {
  return c
      .post("/api/programs/" + name + "/revisions/" + rev + "/state",
            {{"state", state}, {"reason", "test"}}, token)
      .status;
}

const std::string kText = "G21 G90\nN10 G0 X1 Y1\nN20 G1 X5 F300\nM2\n";

TEST(ApiPrograms, AnUploadIsARevisionAddressedByTheHashOfItsBytesWithItsCheck) {
  RunningServer s;
  s.start();
  const ApiClient c = s.client();
  const std::string prog = c.log_in("prog", test::kPassword);
  const test::Reply r = c.post("/api/programs", upload("O100", kText), prog);
  ASSERT_EQ(r.status, 201) << r.body;
  const auto j = r.json();
  EXPECT_EQ(j["name"], "O100");
  EXPECT_EQ(j["revision"], sha256_hex(std::string_view(kText)));
  EXPECT_EQ(j["state"], "draft");
  EXPECT_EQ(j["checks"]["errors"], 0);
  EXPECT_GT(j["checks"]["cycle_time_s"].get<double>(), 0.0);
  EXPECT_EQ(c.post("/api/programs", upload("O100", kText), prog).status, 200);  // same bytes
  const test::Reply bad = c.post("/api/programs", upload("O100", "G1 X1 Q\nM2\n"), prog);
  ASSERT_EQ(bad.status, 201) << bad.body;
  EXPECT_EQ(bad.json()["state"], "check-failed");
  const auto got = c.get("/api/programs/O100", prog).json();
  ASSERT_EQ(got["revisions"].size(), 2U);
  EXPECT_EQ(got["revisions"][0]["state"], "check-failed");  // newest first
  EXPECT_EQ(got["revisions"][1]["revision"], j["revision"]);
  EXPECT_EQ(
      c.get("/api/programs/O100/revisions/" + j["revision"].get<std::string>() + "/text", prog)
          .body,
      kText);
}

TEST(ApiPrograms, StatesMoveByRoleAndEveryIllegalMoveIsRefused) {
  RunningServer s;
  s.start();
  const ApiClient c = s.client();
  const std::string prog = c.log_in("prog", test::kPassword);
  const std::string appr = c.log_in("appr", test::kPassword);
  const std::string oper = c.log_in("oper", test::kPassword);
  const std::string rev = c.post("/api/programs", upload("O200", kText), prog).json()["revision"];
  EXPECT_EQ(move(c, oper, "O200", rev, "checked"), 403);   // an operator moves nothing
  EXPECT_EQ(move(c, prog, "O200", rev, "released"), 409);  // not an edge of the graph
  EXPECT_EQ(move(c, prog, "O200", rev, "checked"), 200);
  EXPECT_EQ(move(c, prog, "O200", rev, "approved"), 403);  // a programmer approves nothing
  EXPECT_EQ(move(c, appr, "O200", rev, "approved"), 200);
  EXPECT_EQ(move(c, appr, "O200", rev, "checked"), 409);  // no way back
  EXPECT_EQ(move(c, appr, "O200", rev, "released"), 200);
  EXPECT_EQ(move(c, appr, "O200", rev, "flying"), 400);  // no such state
  EXPECT_EQ(move(c, appr, "O200", std::string(64, '0'), "rejected"), 404);
  EXPECT_EQ(move(c, appr, "O999", rev, "rejected"), 404);
  const auto got = c.get("/api/programs/O200", oper).json();
  EXPECT_EQ(got["released"], rev);
  EXPECT_EQ(got["revisions"][0]["state"], "released");
}

TEST(ApiPrograms, TheNormalisedDiffIgnoresRenumberingAndThePlainOneDoesNot) {
  RunningServer s;
  s.start();
  const ApiClient c = s.client();
  const std::string prog = c.log_in("prog", test::kPassword);
  const std::string a = c.post("/api/programs", upload("O300", kText), prog).json()["revision"];
  const std::string renumbered = "G21 G90\r\nN100 G0 X1 Y1\r\nN200 G1 X5 F300\r\nM2\r\n";
  const std::string b =
      c.post("/api/programs", upload("O300", renumbered), prog).json()["revision"];
  const std::string base = "/api/programs/O300/diff?from=" + a + "&to=" + b;
  const auto norm = c.get(base + "&normalised=1", prog).json();
  EXPECT_EQ(norm["identical"], true) << norm.dump();
  const auto plain = c.get(base, prog).json();
  EXPECT_EQ(plain["identical"], false);
  EXPECT_NE(plain["diff"].get<std::string>().find("+N100"), std::string::npos);
  EXPECT_EQ(c.get("/api/programs/O300/diff?from=" + a, prog).status, 400);
  EXPECT_EQ(c.get("/api/programs/O300/diff?from=" + a + "&to=" + std::string(64, 'f'), prog).status,
            404);
}

TEST(ApiPrograms, MalformedBodiesAreA400WithAMessage) {
  RunningServer s;
  s.start();
  const ApiClient c = s.client();
  const std::string prog = c.log_in("prog", test::kPassword);
  const auto post_raw = [&](const std::string& body) {
    return c.call(test::bhttp::verb::post, "/api/programs", body, prog);
  };
  for (const std::string body :
       {"{", "[]", "\"text\"", "{\"name\":\"O1\"}", "{\"name\":7,\"text\":\"M2\"}",
        "{\"name\":\"O1\",\"text\":[1]}"}) {
    const test::Reply r = post_raw(body);
    EXPECT_EQ(r.status, 400) << body;
    EXPECT_FALSE(r.json().value("error", "").empty()) << body;
  }
}

TEST(ApiPrograms, NamesAreNeverPaths) {
  RunningServer s;
  s.start();
  const ApiClient c = s.client();
  const std::string prog = c.log_in("prog", test::kPassword);
  EXPECT_EQ(c.post("/api/programs", upload("../etc/passwd", "M2\n"), prog).status, 400);
  EXPECT_EQ(c.post("/api/programs", upload(".hidden", "M2\n"), prog).status, 400);
  EXPECT_EQ(c.get("/api/programs/..%2F..%2Fetc", prog).status, 400);
  EXPECT_EQ(c.get("/api/programs/../audit", prog).status, 400);
  EXPECT_EQ(c.get("/api/programs/NOPE", prog).status, 404);
  EXPECT_EQ(c.get("/api/nothing", prog).status, 404);
}

TEST(ApiPrograms, AnUploadPastTheLimitIs413) {
  RunningServer s;
  ServerConfig config;
  config.max_upload = 4096;
  s.start(config);
  const ApiClient c = s.client();
  const std::string prog = c.log_in("prog", test::kPassword);
  std::string big;
  while (big.size() < 8192)
    big += "G1 X1 Y2 F100\n";
  const test::Reply r = c.post("/api/programs", upload("O400", big), prog);
  EXPECT_EQ(r.status, 413);
  EXPECT_NE(r.body.find("4096"), std::string::npos) << r.body;
  EXPECT_EQ(c.get("/api/programs/O400", prog).status, 404);  // nothing stored
}

TEST(ApiPrograms, AnUploadOfAClassWithAProfileIsCheckedAgainstItsTravel) {
  RunningServer s;
  ServerConfig config;
  core::DiagnosticList diags;
  config.machines.push_back(ServerMachine{LinkConfig{}, "small", "machines/small_vmc.toml"});
  config.machines[0].link.name = "vmc";
  ASSERT_TRUE(load_profiles(config, std::string(USINA_TEST_DIR) + "/../examples", diags));
  config.machines.clear();  // the profile is what this test needs, not the port
  s.start(config);
  const ApiClient c = s.client();
  const std::string prog = c.log_in("prog", test::kPassword);
  // X spans 800 mm; the VMC's X travels 600 (without a work zero the check
  // compares the span with the travel).
  const std::string text = "G21 G90\nG0 X-400 Y0\nG0 X400\nM2\n";
  const auto past =
      c.post("/api/programs", {{"name", "O600"}, {"machine_class", "small"}, {"text", text}}, prog);
  EXPECT_EQ(past.json()["state"], "check-failed") << past.body;
  EXPECT_GE(past.json()["checks"]["overtravel"].get<int>(), 1);
  const auto generic =
      c.post("/api/programs", {{"name", "O601"}, {"machine_class", "other"}, {"text", text}}, prog);
  EXPECT_EQ(generic.json()["state"], "draft") << generic.body;
}

TEST(ApiPrograms, HeadersPastTheLimitAre431) {
  RunningServer s;
  s.start();
  const test::Reply r = s.client().get("/api/programs", std::string(32 * 1024, 'a'));
  EXPECT_EQ(r.status, 431);
}

TEST(ApiAudit, TheLogAndItsChainAreReadByApprovers) {
  RunningServer s;
  s.start();
  const ApiClient c = s.client();
  const std::string prog = c.log_in("prog", test::kPassword);
  c.post("/api/programs", upload("O500", kText), prog);
  const auto j = c.get("/api/audit?verify=1", c.log_in("appr", test::kPassword)).json();
  EXPECT_EQ(j["verify"]["ok"], true);
  EXPECT_GE(j["entries"].size(), 5U);  // users, logins, the upload
  bool upload_seen = false;
  for (const auto& e : j["entries"])
    upload_seen |= e["action"] == "revision.upload" && e["actor"] == "prog";
  EXPECT_TRUE(upload_seen);
  EXPECT_EQ(c.get("/api/audit?limit=x", c.log_in("boss", test::kPassword)).status, 400);
}

}  // namespace
}  // namespace usina::dnc
