// Signed links to a setup sheet (sheet_links.hpp): the page's frame opens
// one without a token; an expired link, a changed one, one moved to
// another revision or format, and one of an earlier server are refused 403.
#include <atomic>

#include <gtest/gtest.h>

#include "dnc/base64.hpp"
#include "dnc/sheet_links.hpp"
#include "server_fixture.hpp"

namespace usina::dnc {
namespace {

using test::ApiClient;
using test::RunningServer;

const std::string kHtml = "<!DOCTYPE html>\n<h1>Setup sheet</h1><script>alert(1)</script>\n";
const std::string kPdf = std::string("%PDF-1.5\n\0\x01\xfe end", 17);

std::atomic<std::int64_t> g_now{1'780'000'000'000'000};

StoreOptions clocked() {
  StoreOptions o = test::fast_store();
  o.now_us = [] { return g_now.load(); };
  return o;
}

// A revision of O400 (its text `text`) with an HTML and a PDF sheet.
std::string with_sheets(const ApiClient& c, const std::string& prog, const std::string& text) {
  const test::Reply r =
      c.post("/api/programs", {{"name", "O400"}, {"dialect", "rs274ngc"}, {"text", text}}, prog);
  EXPECT_EQ(r.status, 201) << r.body;
  const std::string rev = r.json().value("revision", std::string());
  const std::string base = "/api/programs/O400/revisions/" + rev + "/sheet";
  EXPECT_EQ(c.post(base, {{"format", "html"}, {"text", kHtml}}, prog).status, 201);
  EXPECT_EQ(c.post(base, {{"format", "pdf"}, {"text_base64", to_base64(kPdf)}}, prog).status, 201);
  return rev;
}

std::string link_of(const ApiClient& c, const std::string& token, const std::string& rev,
                    const std::string& format) {
  const test::Reply r =
      c.post("/api/programs/O400/revisions/" + rev + "/sheet/link", {{"format", format}}, token);
  EXPECT_EQ(r.status, 200) << r.body;
  return r.json().value("url", std::string());
}

std::string replaced(std::string s, const std::string& from, const std::string& to) {
  const auto at = s.find(from);
  EXPECT_NE(at, std::string::npos) << s << " has no " << from;
  if (at != std::string::npos) s.replace(at, from.size(), to);
  return s;
}

TEST(SheetLinks, ASignatureHoldsForItsFieldsAndKeyOnly) {
  const SheetLinks a(SheetLinks::Key{1}), b(SheetLinks::Key{2});
  const SheetLinkFields f{"O1", "abc", "html", 1000};
  const std::string sig = a.sign(f);
  EXPECT_EQ(sig.size(), 64U);
  EXPECT_TRUE(a.holds(f, sig));
  EXPECT_FALSE(b.holds(f, sig));
  EXPECT_FALSE(a.holds({"O1", "abd", "html", 1000}, sig));
  EXPECT_FALSE(a.holds({"O1", "abc", "pdf", 1000}, sig));
  EXPECT_FALSE(a.holds({"O1", "abc", "html", 1001}, sig));
  EXPECT_FALSE(a.holds({"O2", "abc", "html", 1000}, sig));
  EXPECT_FALSE(a.holds(f, sig.substr(0, 63)));
  EXPECT_FALSE(a.holds(f, sig + "0"));
  EXPECT_FALSE(a.holds(f, std::string(64, 'g')));
  EXPECT_FALSE(a.holds(f, ""));
  EXPECT_NE(SheetLinks().sign(f), SheetLinks().sign(f));  // each server its own key
}

TEST(ApiSheetLinks, ALinkOpensTheSheetWithoutATokenUntilItExpires) {
  RunningServer s;
  s.start({}, clocked());
  const ApiClient c = s.client();
  const std::string oper = c.log_in("oper", test::kPassword);
  const std::string rev = with_sheets(c, c.log_in("prog", test::kPassword), "G0 X1\nM2\n");
  const test::Reply link =
      c.post("/api/programs/O400/revisions/" + rev + "/sheet/link", {{"format", "html"}}, oper);
  ASSERT_EQ(link.status, 200) << link.body;
  EXPECT_EQ(link.json()["expires_at_us"], (g_now / 1'000'000 + kSheetLinkSeconds) * 1'000'000);
  const std::string url = link.json()["url"];
  test::Reply r = c.get(url);
  ASSERT_EQ(r.status, 200) << r.body;
  EXPECT_EQ(r.body, kHtml);
  EXPECT_EQ(r.header("content-security-policy").rfind("sandbox;", 0), 0U);
  EXPECT_EQ(r.header("cache-control"), "no-store");
  r = c.get(link_of(c, oper, rev, "pdf"));
  ASSERT_EQ(r.status, 200);
  EXPECT_EQ(r.body, kPdf);
  EXPECT_EQ(r.header("content-type"), "application/pdf");
  g_now += (kSheetLinkSeconds - 1) * 1'000'000;
  EXPECT_EQ(c.get(url).status, 200);
  g_now += 1'000'000;
  r = c.get(url);
  EXPECT_EQ(r.status, 403);
  EXPECT_NE(r.body.find("expired"), std::string::npos) << r.body;
}

TEST(ApiSheetLinks, AChangedOrMovedLinkIsRefused) {
  RunningServer s;
  s.start({}, clocked());
  const ApiClient c = s.client();
  const std::string prog = c.log_in("prog", test::kPassword);
  const std::string rev = with_sheets(c, prog, "G0 X1\nM2\n");
  const std::string other = with_sheets(c, prog, "G0 X2\nM2\n");
  const std::string url = link_of(c, prog, rev, "html");
  const auto refused = [&](const std::string& bad, const std::string& why) {
    const test::Reply r = c.get(bad);
    EXPECT_EQ(r.status, 403) << bad << ": " << r.body;
    EXPECT_NE(r.body.find(why), std::string::npos) << r.body;
    EXPECT_EQ(r.body.find("Setup sheet"), std::string::npos);
  };
  const std::string sig = url.substr(url.find("sig=") + 4);
  const std::string flipped = std::string(1, sig[0] == 'a' ? 'b' : 'a') + sig.substr(1);
  refused(replaced(url, sig, flipped), "does not hold");
  refused(replaced(url, "/revisions/" + rev, "/revisions/" + other), "does not hold");
  refused(replaced(url, "format=html", "format=pdf"), "does not hold");
  const std::string expires = url.substr(url.find("expires=") + 8, 10);
  refused(
      replaced(url, "expires=" + expires, "expires=" + std::to_string(std::stoll(expires) + 600)),
      "does not hold");
  refused(replaced(url, "&sig=" + sig, ""), "incomplete");
  refused(replaced(url, "expires=" + expires, "expires=soon"), "incomplete");
  EXPECT_EQ(c.get(url).status, 200);  // the link itself still opens
  // A link is only made for a sheet there is.
  const std::string base = "/api/programs/O400/revisions/";
  EXPECT_EQ(c.post(base + rev + "/sheet/link", {{"format", "doc"}}, prog).status, 400);
  EXPECT_EQ(c.post(base + rev + "/sheet/link", nlohmann::json::object(), prog).status, 400);
  EXPECT_EQ(c.post(base + std::string(64, 'e') + "/sheet/link", {{"format", "html"}}, prog).status,
            404);
  EXPECT_EQ(c.post(base + rev + "/sheet/link", {{"format", "html"}}).status, 401);
}

TEST(ApiSheetLinks, ALinkOfAnEarlierServerIsRefused) {
  RunningServer first;
  first.start({}, clocked());
  const ApiClient c1 = first.client();
  const std::string prog = c1.log_in("prog", test::kPassword);
  const std::string url = link_of(c1, prog, with_sheets(c1, prog, "G0 X1\nM2\n"), "html");
  first.stop();
  RunningServer second;
  second.use_store(first.where());
  second.start({}, clocked());
  const test::Reply r = second.client().get(url);
  EXPECT_EQ(r.status, 403) << r.body;
  EXPECT_NE(r.body.find("before the server restarted"), std::string::npos) << r.body;
}

}  // namespace
}  // namespace usina::dnc
