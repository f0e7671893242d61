// POST /api/import and GET /api/export: a JSON list of files in (each a
// revision, as the folder import makes them; names never paths; bytes that
// are not UTF-8 as base64), the released set out as a tar that `tar x` and
// `sha256sum -c` accept; roles, limits and malformed requests.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "api_control.hpp"
#include "dnc/export_stream.hpp"
#include "dnc/sha256.hpp"
#include "dnc/store_blobs.hpp"
#include "dnc/store_db.hpp"
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

// A program several times the export's piece (64 KiB), with 5-digit N words.
std::string big_program() {
  std::string text = "G21 G90\n";
  for (int i = 1; i <= 20'000; ++i)
    text += fmt::format("N{} G1 X{}.{} F500\n", i, i % 97, i % 10);
  return text + "M2\n";
}

// `curl` of the export: its exit status, the head it read into `head`.
test::Run curl_export(RunningServer& s, const std::string& token, const test::TempDir& out) {
  return test::shell(
      fmt::format("curl -sS -D {} -o {} -H 'Authorization: Bearer {}' "
                  "http://127.0.0.1:{}/api/export?state=released 2>{}",
                  test::quote(out.path("head")), test::quote(out.path("released.tar")), token,
                  s.server().endpoint().port(), test::quote(out.path("err"))),
      out.path("err"));
}

TEST(ApiExport, ASetLargerThanAPieceStreamsWithItsLengthKnownAndUnpacks) {
  RunningServer s;
  s.start();
  const ApiClient c = s.client();
  const std::string big = big_program();
  ASSERT_GT(big.size(), 4 * kExportPieceBytes);
  released(c, "BIG", big);
  released(c, "O500", "G0 X1\nG1 X2 F100\nM2\n");
  const std::string prog = c.log_in("prog", test::kPassword);
  const test::TempDir out;
  const auto got = curl_export(s, prog, out);
  ASSERT_EQ(got.status, 0) << got.err;
  const std::string head = out.read("head");
  const std::string tar = out.read("released.tar");
  // 3 headers, BIG padded, O500 in one block, the manifest in one, the end.
  const std::size_t padded = (big.size() + 511) / 512 * 512;
  EXPECT_EQ(tar.size(), 3 * 512 + padded + 512 + 512 + 1024);
  EXPECT_NE(head.find(fmt::format("Content-Length: {}\r\n", tar.size())), std::string::npos)
      << head;
  EXPECT_EQ(head.find("Transfer-Encoding"), std::string::npos) << head;
  const auto unpacked = test::shell("cd " + test::quote(out.path()) +
                                        " && tar -xf released.tar && sha256sum -c "
                                        "released.sha256 2>" +
                                        test::quote(out.path("err")),
                                    out.path("err"));
  EXPECT_EQ(unpacked.status, 0) << unpacked.out << unpacked.err;
  EXPECT_EQ(out.read("BIG.nc"), big);
  // The same bytes through Beast's client, on a connection kept alive for a next request.
  const auto again = c.get("/api/export?state=released", prog);
  ASSERT_EQ(again.status, 200);
  EXPECT_EQ(again.body.size(), tar.size());
  EXPECT_EQ(again.body.substr(512, big.size()), big);
}

TEST(ApiExport, ADamagedRevisionCutsTheStreamShortOfItsLength) {
  RunningServer s;
  s.start();
  const ApiClient c = s.client();
  released(c, "BIG", big_program());
  const std::string rev = released(c, "O500", "G0 X1\nG1 X2 F100\nM2\n");
  // Someone edits the second file's blob in the database (its trigger dropped first).
  const bool tampered = s.on_loop([&] {
    Database& db = s.server().store().db();
    return db.script("DROP TRIGGER blobs_no_update").has_value() &&
           db.query("UPDATE blobs SET bytes = $1 WHERE hash = $2",
                    {SqlBlob{std::string_view("G0 X9\nM2\n")}, std::string_view(rev)})
               .has_value();
  });
  ASSERT_TRUE(tampered);
  const test::TempDir out;
  const auto got = curl_export(s, c.log_in("prog", test::kPassword), out);
  EXPECT_EQ(got.status, 18) << got.err;  // curl: partial file
  EXPECT_LT(out.read("released.tar").size(), big_program().size() + 3 * 512 + 1024);
  EXPECT_GT(out.read("released.tar").size(), big_program().size());  // BIG went out whole
}

// A revision larger than a piece is read and hashed piece by piece: its
// damage shows only at its end, after most of it went out, and the stream
// still stops short of its length.
TEST(ApiExport, ALargeDamagedRevisionStopsTheStreamAtItsLastPiece) {
  RunningServer s;
  s.start();
  const ApiClient c = s.client();
  const std::string big = big_program();
  const std::string rev = released(c, "BIG", big);
  std::string changed = big;
  changed[big.size() / 2] = changed[big.size() / 2] == '1' ? '2' : '1';  // same length
  const bool tampered = s.on_loop([&] {
    Database& db = s.server().store().db();
    return db.script("DROP TRIGGER blobs_no_update").has_value() &&
           db.query("UPDATE blobs SET bytes = $1 WHERE hash = $2",
                    {SqlBlob{changed}, std::string_view(rev)})
               .has_value();
  });
  ASSERT_TRUE(tampered);
  const test::TempDir out;
  const auto got = curl_export(s, c.log_in("prog", test::kPassword), out);
  EXPECT_EQ(got.status, 18) << got.err;  // curl: partial file
  const std::string tar = out.read("released.tar");
  // The header and every piece but the last went out; the last did not.
  const std::size_t whole_pieces = big.size() / kExportPieceBytes;
  EXPECT_EQ(tar.size(), 512 + whole_pieces * kExportPieceBytes);
  EXPECT_EQ(tar.substr(512), changed.substr(0, whole_pieces * kExportPieceBytes));
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

namespace usina::dnc {
namespace {

// Kilobytes of a /proc/self/status field ("VmHWM", "VmRSS").
long status_kib(const std::string& field) {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line))
    if (line.starts_with(field + ":")) return std::stol(line.substr(field.size() + 1));
  return -1;
}

// A released revision written straight into the store at `where` (a
// revision past the API's 64 MiB upload limit, without its check: the
// export reads only the blob and the revision's row), through a connection
// of its own, closed after, as if an earlier run had stored it.
bool store_released(const std::string& where, const std::string& name, const std::string& text) {
  auto store = Store::open(where);
  if (!store) return false;
  Store& s = **store;
  const std::string hash = sha256_hex(std::string_view(text));
  const auto size = static_cast<std::int64_t>(text.size());
  Transaction tx(s.db());
  return tx.begin_write().has_value() && put_blob(s, hash, text).has_value() &&
         s.db()
             .query(
                 "INSERT INTO programs (name, machine_class, dialect, created_at) "
                 "VALUES ($1, 'default', 'rs274ngc', 0)",
                 {std::string_view(name)})
             .has_value() &&
         s.db()
             .query(
                 "INSERT INTO revisions (program, hash, size, author, created_at, reason, "
                 "dialect, state, state_at, check_errors, checks) VALUES ($1, $2, $3, "
                 "'boss', 0, '', 'rs274ngc', 'released', 0, 0, '{}')",
                 {std::string_view(name), std::string_view(hash), size})
             .has_value() &&
         tx.commit().has_value();
}

// The figure of docs/dnc.md: the peak memory of the server's process while
// it exports a large set (USINA_EXPORT_RSS_MIB of programs of
// USINA_EXPORT_PROGRAM_MIB each, 4 by default):
//   USINA_EXPORT_RSS_MIB=512 build/tests/dnc_tests --gtest_filter='ApiExportMemory.*'
//   USINA_EXPORT_RSS_MIB=256 USINA_EXPORT_PROGRAM_MIB=256 build/tests/dnc_tests
//     --gtest_filter='ApiExportMemory.*'   (one revision of 256 MiB)
// With USINA_EXPORT_STORE=postgresql://... (an empty database, such as the
// one `tests/dnc/pg_cluster.sh start DIR` prints) the server's store is
// PostgreSQL (the peak is the server's process, not PostgreSQL's).
TEST(ApiExportMemory, ThePeakGrowsByAboutOnePieceNotTheRevisionOrTheSet) {
  const char* mib = std::getenv("USINA_EXPORT_RSS_MIB");
  if (mib == nullptr) GTEST_SKIP() << "a measurement: set USINA_EXPORT_RSS_MIB (e.g. 512)";
  const char* each = std::getenv("USINA_EXPORT_PROGRAM_MIB");
  const int program_mib = each != nullptr ? std::max(1, std::atoi(each)) : 4;
  RunningServer s;
  const char* given = std::getenv("USINA_EXPORT_STORE");
  if (given != nullptr) s.use_store(given);
  s.start();
  const ApiClient c = s.client();
  const int programs = std::max(1, std::atoi(mib) / program_mib);
  {
    std::string text = "G21 G90\n";
    while (text.size() < (static_cast<std::size_t>(program_mib) << 20))
      text += "G1 X10.5 Y20.25 F500\nG1 X0 Y0\n";
    for (int i = 0; i < programs; ++i) {
      const std::string name = fmt::format("P{:04}", i);
      const std::string body = text + fmt::format("(PROGRAM {})\nM2\n", i);
      if (program_mib <= 32) {
        released(c, name, body);
      } else {
        ASSERT_TRUE(store_released(given != nullptr ? given : s.dir(), name, body));
      }
    }
  }
  const std::string prog = c.log_in("prog", test::kPassword);
  const long before = status_kib("VmRSS");
  {
    std::ofstream reset("/proc/self/clear_refs");
    reset << "5";  // the peak (VmHWM) starts again from now
  }
  const test::TempDir out;
  const auto got = curl_export(s, prog, out);
  ASSERT_EQ(got.status, 0) << got.err;
  const long peak = status_kib("VmHWM");
  const auto size = std::filesystem::file_size(out.path("released.tar"));
  std::printf(
      "export of %d programs of %d MiB, %.0f MiB: RSS before %.1f MiB, peak during %.1f MiB\n",
      programs, program_mib, static_cast<double>(size) / (1 << 20),
      static_cast<double>(before) / 1024, static_cast<double>(peak) / 1024);
  EXPECT_LT(peak - before, 16L * 1024);  // KiB: a few pieces, whatever the revision's size
}

}  // namespace
}  // namespace usina::dnc
