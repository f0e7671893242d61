// POST /api/import and GET /api/export: a JSON list of files in (each a
// revision, as the folder import makes them; names never paths; bytes that
// are not UTF-8 as base64), the released set out as a tar that `tar x` and
// `sha256sum -c` accept; roles, limits and malformed requests.
#include <gtest/gtest.h>

#include "api_control.hpp"
#include "dnc/sha256.hpp"
#include "support/files.hpp"
#include "support/usina_process.hpp"

namespace usina::dnc {
namespace {

const std::string kLatin1 =
    "O200\n(PE\xc7"
    "A)\nG0 X1\nM2\n";  // a Latin-1 comment

nlohmann::json file(const std::string& name, const std::string& text) {
  return {{"name", name}, {"text", text}};
}

TEST(ApiImport, EachFileIsARevisionAndBadNamesAreSkippedWithTheirReason) {
  RunningServer s;
  s.start();
  const ApiClient c = s.client();
  const std::string boss = c.log_in("boss", test::kPassword);
  const nlohmann::json body = {
      {"files",
       {file("O100.nc", "G0 X1\nM2\n"),
        {{"name", "O200.nc"}, {"text_base64", "TzIwMApHMCBYMQpNMgo="}},  // "O200\nG0 X1\nM2\n"
        file("../etc/passwd", "G0 X1\n"),
        file("O100.txt", "G0 X2\nM2\n"),
        file("/abs.nc", "G0 X1\n"),
        {{"name", "O300"}}}},
      {"reason", "from the old DNC PC"}};
  const auto r = c.post("/api/import", body, boss);
  ASSERT_EQ(r.status, 200) << r.body;
  const auto j = r.json();
  EXPECT_EQ(j["imported"], 2);
  EXPECT_EQ(j["skipped"], 4);
  ASSERT_EQ(j["files"].size(), 6u);
  EXPECT_EQ(j["files"][0]["program"], "O100");
  EXPECT_EQ(j["files"][0]["revision"], sha256_hex(std::string_view("G0 X1\nM2\n")));
  EXPECT_EQ(j["files"][1]["revision"], sha256_hex(std::string_view("O200\nG0 X1\nM2\n")));
  for (int i = 2; i < 6; ++i)
    EXPECT_NE(j["files"][i]["error"], "") << j["files"][i].dump();
  EXPECT_TRUE(test::contains(j["files"][3]["error"].get<std::string>(), "program O100 already"));
  const auto o100 = c.get("/api/programs/O100", boss).json();
  EXPECT_EQ(o100["revisions"][0]["state"], "draft");
  EXPECT_TRUE(
      test::contains(o100["revisions"][0]["reason"].get<std::string>(), "from the old DNC PC"));
  EXPECT_EQ(c.get("/api/programs/passwd", boss).status, 404);
  // Again: nothing new.
  const auto again = c.post("/api/import", {{"files", {file("O100.nc", "G0 X1\nM2\n")}}}, boss);
  EXPECT_EQ(again.json()["unchanged"], 1);
  EXPECT_EQ(again.json()["imported"], 0);
}

TEST(ApiImport, MalformedListsAre400AndStoreNothing) {
  RunningServer s;
  s.start();
  const ApiClient c = s.client();
  const std::string boss = c.log_in("boss", test::kPassword);
  EXPECT_EQ(c.post("/api/import", {{"files", "O1.nc"}}, boss).status, 400);
  EXPECT_EQ(c.post("/api/import", {{"files", nlohmann::json::array()}}, boss).status, 400);
  EXPECT_EQ(c.post("/api/import", {{"files", {file("O1.nc", "G0\n"), 5}}}, boss).status, 400);
  EXPECT_EQ(
      c.post("/api/import", {{"files", {file("O1.nc", "G0\n")}}, {"dialect", 3}}, boss).status,
      400);
  nlohmann::json many = nlohmann::json::array();
  for (int i = 0; i < 1001; ++i)
    many.push_back(file("O" + std::to_string(i), "G0\n"));
  EXPECT_EQ(c.post("/api/import", {{"files", many}}, boss).status, 400);
  EXPECT_EQ(c.get("/api/programs", boss).json()["programs"].size(), 0u);
  // Both forms, or a base64 that is none: that file is skipped.
  const auto both = c.post("/api/import",
                           {{"files",
                             {{{"name", "O1"}, {"text", "G0\n"}, {"text_base64", "RzAK"}},
                              {{"name", "O2"}, {"text_base64", "not base64!"}}}}},
                           boss);
  ASSERT_EQ(both.status, 200);
  EXPECT_EQ(both.json()["skipped"], 2);
}

TEST(ApiImport, ABodyPastTheUploadLimitIs413) {
  RunningServer s;
  ServerConfig config;
  config.max_upload = 4096;
  s.start(config);
  const ApiClient c = s.client();
  const std::string boss = c.log_in("boss", test::kPassword);
  const auto r = c.post("/api/import", {{"files", {file("O1.nc", std::string(8000, 'X'))}}}, boss);
  EXPECT_EQ(r.status, 413);
}

TEST(ApiExport, TheReleasedSetIsATarThatSha256sumChecks) {
  RunningServer s;
  s.start();
  const ApiClient c = s.client();
  const std::string boss = c.log_in("boss", test::kPassword);
  const std::string text = "G0 X1\nG1 X2 F100\nM2\n";
  released(c, "O500", text);
  // Bytes that are not UTF-8 go in as base64 and come out as they are.
  const auto imported = c.post(
      "/api/import",
      {{"files", {{{"name", "O200.nc"}, {"text_base64", "TzIwMAooUEXHQSkKRzAgWDEKTTIK"}}}}}, boss);
  ASSERT_EQ(imported.json()["imported"], 1) << imported.body;
  const std::string rev = imported.json()["files"][0]["revision"];
  EXPECT_EQ(rev, sha256_hex(std::string_view(kLatin1)));
  for (const char* state : {"checked", "approved", "released"})
    c.post("/api/programs/O200/revisions/" + rev + "/state", {{"state", state}}, boss);
  c.post("/api/programs", {{"name", "O600"}, {"text", "G0 X5\nM2\n"}}, boss);  // a draft: not out
  const std::string prog = c.log_in("prog", test::kPassword);
  const auto tar = c.get("/api/export?state=released", prog);
  ASSERT_EQ(tar.status, 200) << tar.body;
  const test::TempDir out;
  out.write("released.tar", tar.body);
  const auto unpacked = test::shell("cd " + test::quote(out.path()) +
                                        " && tar -xf released.tar && sha256sum -c "
                                        "released.sha256 2>" +
                                        test::quote(out.path("err")),
                                    out.path("err"));
  EXPECT_EQ(unpacked.status, 0) << unpacked.out << unpacked.err;
  EXPECT_EQ(out.read("O500.nc"), text);
  EXPECT_EQ(out.read("O200.nc"), kLatin1);
  EXPECT_FALSE(test::exists(out.path("O600.nc")));
  EXPECT_EQ(test::lines(out.read("released.sha256")).size(), 2u);
  const auto audit = c.get("/api/audit", boss).json()["entries"];
  EXPECT_EQ(audit.back()["action"], "export.released");
}

TEST(ApiExport, OnlyTheReleasedStateAndPlainExtensions) {
  RunningServer s;
  s.start();
  const ApiClient c = s.client();
  const std::string prog = c.log_in("prog", test::kPassword);
  EXPECT_EQ(c.get("/api/export?state=approved", prog).status, 400);
  EXPECT_EQ(c.get("/api/export?extension=..%2Fx", prog).status, 400);
  EXPECT_EQ(c.get("/api/export?extension=toolongext", prog).status, 400);
  const auto empty = c.get("/api/export?extension=MIN", prog);
  ASSERT_EQ(empty.status, 200);
  EXPECT_EQ(empty.body.size(), 3u * 512u);  // the manifest's header and two end blocks
  EXPECT_EQ(c.get("/api/export", c.log_in("oper", test::kPassword)).status, 403);
}

}  // namespace
}  // namespace usina::dnc
