// A revision's setup sheet over HTTP: put as JSON (HTML as text, a PDF as
// base64), read back as its bytes with its type (HTML sandboxed), listed
// with the revision, audited, announced; refused for a bad body (400), an
// unknown revision (404), a role that may not (403); and the whole road:
// `usina job --sheet` writes a program and its PDF, both go up, the sheet
// comes back byte for byte.
#include <gtest/gtest.h>

#include "dnc/base64.hpp"
#include "dnc/sha256.hpp"
#include "server_fixture.hpp"
#include "support/files.hpp"
#include "support/usina_process.hpp"

namespace usina::dnc {
namespace {

using test::ApiClient;
using test::RunningServer;

const std::string kText = "G21 G90\nG0 X1 Y1\nG1 X5 F300\nM2\n";
const std::string kHtml = "<!DOCTYPE html>\n<h1>Setup sheet: O300</h1>\n";
const std::string kPdf = std::string("%PDF-1.5\n\0\x01\xfe end", 17);

std::string revision_of(const ApiClient& c, const std::string& token) {
  const test::Reply r =
      c.post("/api/programs", {{"name", "O300"}, {"dialect", "rs274ngc"}, {"text", kText}}, token);
  EXPECT_EQ(r.status, 201) << r.body;
  return r.json().value("revision", std::string());
}

TEST(ApiSheets, ASheetPutWithItsRevisionIsReadBackWithItsType) {
  RunningServer s;
  s.start();
  const ApiClient c = s.client();
  const std::string prog = c.log_in("prog", test::kPassword);
  const std::string oper = c.log_in("oper", test::kPassword);
  const std::string rev = revision_of(c, prog);
  const std::string base = "/api/programs/O300/revisions/" + rev;
  test::Reply r = c.post(base + "/sheet", {{"format", "html"}, {"text", kHtml}}, prog);
  ASSERT_EQ(r.status, 201) << r.body;
  EXPECT_EQ(r.json()["sheet"], sha256_hex(std::string_view(kHtml)));
  EXPECT_EQ(r.json()["replaced"], nullptr);
  r = c.post(base + "/sheet", {{"format", "pdf"}, {"text_base64", to_base64(kPdf)}}, prog);
  ASSERT_EQ(r.status, 201) << r.body;
  EXPECT_EQ(
      c.post(base + "/sheet", {{"format", "pdf"}, {"text_base64", to_base64(kPdf)}}, prog).status,
      200);  // the same bytes again
  // Every role reads it: the PDF first, the HTML when asked for, sandboxed.
  r = c.get(base + "/sheet", oper);
  ASSERT_EQ(r.status, 200) << r.body;
  EXPECT_EQ(r.body, kPdf);
  EXPECT_EQ(r.header("content-type"), "application/pdf");
  r = c.get(base + "/sheet?format=html", oper);
  ASSERT_EQ(r.status, 200);
  EXPECT_EQ(r.body, kHtml);
  EXPECT_EQ(r.header("content-type"), "text/html; charset=utf-8");
  EXPECT_EQ(r.header("content-security-policy").rfind("sandbox;", 0), 0u)
      << r.header("content-security-policy");
  const auto sheets = c.get(base, oper).json()["sheets"];
  ASSERT_EQ(sheets.size(), 2u);
  EXPECT_EQ(sheets[0]["format"], "html");
  EXPECT_EQ(sheets[1]["size"], kPdf.size());
  const auto audit = c.get("/api/audit", c.log_in("boss", test::kPassword)).json()["entries"];
  std::size_t sheet_entries = 0;
  for (const auto& e : audit)
    sheet_entries += e["action"] == "revision.sheet" ? 1 : 0;
  EXPECT_EQ(sheet_entries, 2u);
}

TEST(ApiSheets, BadSheetsAre400UnknownRevisions404AndOperators403) {
  RunningServer s;
  s.start();
  const ApiClient c = s.client();
  const std::string prog = c.log_in("prog", test::kPassword);
  const std::string rev = revision_of(c, prog);
  const std::string sheet = "/api/programs/O300/revisions/" + rev + "/sheet";
  using J = nlohmann::json;
  for (const J& body :
       {J{{"text", kHtml}}, J{{"format", "html"}},
        J{{"format", "html"}, {"text", kHtml}, {"text_base64", "eA=="}},
        J{{"format", "pdf"}, {"text_base64", "not base64!"}}, J{{"format", "pdf"}, {"text", kHtml}},
        J{{"format", "odt"}, {"text", "x"}}, J{{"format", 5}, {"text", kHtml}}})
    EXPECT_EQ(c.post(sheet, body, prog).status, 400) << body.dump();
  EXPECT_EQ(c.call(test::bhttp::verb::post, sheet, "{", prog).status, 400);
  EXPECT_EQ(c.get(sheet, prog).status, 404);  // none yet
  EXPECT_EQ(c.get(sheet + "?format=doc", prog).status, 400);
  const J good{{"format", "html"}, {"text", kHtml}};
  EXPECT_EQ(
      c.post("/api/programs/O300/revisions/" + std::string(64, 'a') + "/sheet", good, prog).status,
      404);
  EXPECT_EQ(c.post("/api/programs/O999/revisions/" + rev + "/sheet", good, prog).status, 404);
  EXPECT_EQ(c.post(sheet, good, c.log_in("oper", test::kPassword)).status, 403);
  EXPECT_EQ(c.get(sheet, prog).status, 404);  // nothing was stored
}

TEST(ApiSheets, TheSheetUsinaJobWroteComesBackWithItsProgram) {
  const usina::test::TempDir dir;
  const std::string job = std::string(USINA_TEST_DIR) + "/../examples/jobs/plate.toml";
  const usina::test::Run made =
      usina::test::usina("job " + usina::test::quote(job) + " --post fanuc -o " +
                         usina::test::quote(dir.path("plate.nc")) + " --sheet " +
                         usina::test::quote(dir.path("plate.pdf")));
  ASSERT_EQ(made.status, 0) << made.err;
  const std::string pdf = usina::test::slurp(dir.path("plate.pdf"));
  RunningServer s;
  s.start();
  const ApiClient c = s.client();
  const std::string prog = c.log_in("prog", test::kPassword);
  const test::Reply up = c.post("/api/programs",
                                {{"name", "PLATE"},
                                 {"dialect", "fanuc"},
                                 {"text", usina::test::slurp(dir.path("plate.nc"))},
                                 {"reason", "from examples/jobs/plate.toml"}},
                                prog);
  ASSERT_EQ(up.status, 201) << up.body;
  const std::string sheet =
      "/api/programs/PLATE/revisions/" + up.json()["revision"].get<std::string>() + "/sheet";
  ASSERT_EQ(c.post(sheet, {{"format", "pdf"}, {"text_base64", to_base64(pdf)}}, prog).status, 201);
  const test::Reply back = c.get(sheet, c.log_in("oper", test::kPassword));
  ASSERT_EQ(back.status, 200);
  EXPECT_EQ(back.body, pdf);
  EXPECT_EQ(back.header("content-type"), "application/pdf");
}

}  // namespace
}  // namespace usina::dnc
