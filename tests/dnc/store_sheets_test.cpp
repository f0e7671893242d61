// A revision's setup sheet in the store (store_sheets.hpp), on SQLite and
// PostgreSQL: stored as a blob and read back verified, the PDF preferred
// when both are there, a later sheet replacing the one before with an
// audit entry naming it, the same bytes again changing nothing, and every
// bad sheet refused with nothing written.
#include "dnc/store_sheets.hpp"

#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "dnc/sha256.hpp"
#include "dnc/store_audit.hpp"
#include "dnc/store_revisions.hpp"
#include "store_fixture.hpp"

namespace usina::dnc {
namespace {

class StoreSheets : public test::StoreTest {
 protected:
  // A store with program O1 of one revision; the revision's hash.
  std::string with_revision(Store& s) {
    auto put = put_revision(s, {"O1", "", "rs274ngc", "G0 X1\nM2\n", "first", nullptr}, kProg);
    EXPECT_TRUE(put) << put.error().message;
    return put ? put->revision.hash : "";
  }

  std::int64_t audit_entries(Store& s) {
    auto entries = read_audit(s, 0, 1000);
    EXPECT_TRUE(entries);
    return entries ? static_cast<std::int64_t>(entries->size()) : -1;
  }

  const Actor kProg{"pat", "10.0.0.3"};
};

const std::string kHtml = "<!DOCTYPE html>\n<title>Setup sheet: O1</title>\n";
const std::string kPdf = std::string("%PDF-1.5\n\0\xff binary", 19);

TEST_P(StoreSheets, ASheetIsStoredWithItsRevisionAndReadBackVerified) {
  auto store = open();
  ASSERT_TRUE(store);
  const std::string rev = with_revision(*store);
  auto html = put_sheet(*store, {"O1", rev, "html", kHtml, "from usina job"}, kProg);
  ASSERT_TRUE(html) << html.error().message;
  EXPECT_TRUE(html->changed);
  EXPECT_FALSE(html->replaced);
  EXPECT_EQ(html->sheet.hash, sha256_hex(std::string_view(kHtml)));
  auto read = read_sheet(*store, "O1", rev, std::nullopt);
  ASSERT_TRUE(read) << read.error().message;
  EXPECT_EQ(read->second, kHtml);
  ASSERT_TRUE(put_sheet(*store, {"O1", rev, "pdf", kPdf, ""}, kProg));
  // Both stored: the PDF unless the HTML is asked for.
  read = read_sheet(*store, "O1", rev, std::nullopt);
  ASSERT_TRUE(read);
  EXPECT_EQ(read->first.format, "pdf");
  EXPECT_EQ(read->second, kPdf);
  read = read_sheet(*store, "O1", rev, "html");
  ASSERT_TRUE(read);
  EXPECT_EQ(read->second, kHtml);
  auto list = list_sheets(*store, "O1", rev);
  ASSERT_TRUE(list);
  ASSERT_EQ(list->size(), 2u);
  EXPECT_EQ((*list)[0].format, "html");
  EXPECT_EQ((*list)[1].size, static_cast<std::int64_t>(kPdf.size()));
  EXPECT_EQ((*list)[1].author, "pat");
}

TEST_P(StoreSheets, ALaterSheetReplacesTheOneBeforeAndTheAuditNamesIt) {
  auto store = open();
  ASSERT_TRUE(store);
  const std::string rev = with_revision(*store);
  ASSERT_TRUE(put_sheet(*store, {"O1", rev, "html", kHtml, ""}, kProg));
  const std::int64_t before = audit_entries(*store);
  auto same = put_sheet(*store, {"O1", rev, "html", kHtml, ""}, kProg);
  ASSERT_TRUE(same);
  EXPECT_FALSE(same->changed);
  EXPECT_EQ(audit_entries(*store), before);  // nothing new to record
  const std::string corrected = kHtml + "<p>vise on the left</p>\n";
  auto put = put_sheet(*store, {"O1", rev, "html", corrected, "jaws corrected"}, kProg);
  ASSERT_TRUE(put) << put.error().message;
  ASSERT_TRUE(put->replaced);
  EXPECT_EQ(*put->replaced, sha256_hex(std::string_view(kHtml)));
  EXPECT_EQ(read_sheet(*store, "O1", rev, "html")->second, corrected);
  auto entries = read_audit(*store, 0, 1000);
  ASSERT_TRUE(entries);
  const AuditEntry& last = entries->back();
  EXPECT_EQ(last.action, "revision.sheet");
  EXPECT_EQ(last.subject, "O1@" + rev);
  EXPECT_EQ(last.reason, "jaws corrected");
  EXPECT_EQ(last.origin, "10.0.0.3");
  const auto detail = nlohmann::json::parse(last.detail);
  EXPECT_EQ(detail["format"], "html");
  EXPECT_EQ(detail["sheet"], sha256_hex(std::string_view(corrected)));
  EXPECT_EQ(detail["replaced"], sha256_hex(std::string_view(kHtml)));
  auto verdict = verify_audit(*store);
  ASSERT_TRUE(verdict);
  EXPECT_TRUE(verdict->ok);
}

TEST_P(StoreSheets, EveryBadSheetIsRefusedWithNothingWritten) {
  StoreOptions o = options();
  o.max_program_bytes = 64;
  auto store = open(o);
  ASSERT_TRUE(store);
  const std::string rev = with_revision(*store);
  const std::int64_t before = audit_entries(*store);
  const auto kind = [&](SheetUpload u) {
    auto r = put_sheet(*store, u, kProg);
    return r ? std::optional<StoreErrorKind>() : r.error().kind;
  };
  EXPECT_EQ(kind({"O1", rev, "docx", kHtml, ""}), StoreErrorKind::Invalid);
  EXPECT_EQ(kind({"O1", rev, "html", "", ""}), StoreErrorKind::Invalid);
  EXPECT_EQ(kind({"O1", rev, "pdf", kHtml, ""}), StoreErrorKind::Invalid);  // not a PDF
  EXPECT_EQ(kind({"O1", rev, "html", kPdf, ""}), StoreErrorKind::Invalid);  // a PDF
  EXPECT_EQ(kind({"O1", rev, "html", std::string("a\0b", 3), ""}), StoreErrorKind::Invalid);
  EXPECT_EQ(kind({"O1", rev, "html", std::string(65, 'x'), ""}), StoreErrorKind::TooLarge);
  EXPECT_EQ(kind({"O1", rev, "html", kHtml, std::string("a\0b", 3)}), StoreErrorKind::Invalid);
  EXPECT_EQ(kind({"O1", std::string(64, '0'), "html", kHtml, ""}), StoreErrorKind::NotFound);
  EXPECT_EQ(kind({"O2", rev, "html", kHtml, ""}), StoreErrorKind::NotFound);
  EXPECT_EQ(audit_entries(*store), before);
  auto list = list_sheets(*store, "O1", rev);
  ASSERT_TRUE(list);
  EXPECT_TRUE(list->empty());
  EXPECT_EQ(read_sheet(*store, "O1", rev, std::nullopt).error().kind, StoreErrorKind::NotFound);
  EXPECT_EQ(read_sheet(*store, "O1", rev, "docx").error().kind, StoreErrorKind::Invalid);
  EXPECT_EQ(read_sheet(*store, "O1", "nope", std::nullopt).error().kind, StoreErrorKind::NotFound);
}

TEST_P(StoreSheets, ASheetWhoseBytesChangedInTheDatabaseIsNotHandedOut) {
  auto store = open();
  ASSERT_TRUE(store);
  const std::string rev = with_revision(*store);
  auto put = put_sheet(*store, {"O1", rev, "pdf", kPdf, ""}, kProg);
  ASSERT_TRUE(put);
  auto db = raw();
  ASSERT_TRUE(db);
  drop_trigger(*db, "blobs_no_update", "blobs");
  ASSERT_TRUE(
      db->query("UPDATE blobs SET bytes = $1 WHERE hash = $2",
                {SqlBlob{std::string_view("%PDF-1.5 forged")}, std::string_view(put->sheet.hash)}));
  EXPECT_EQ(read_sheet(*store, "O1", rev, "pdf").error().kind, StoreErrorKind::Damaged);
}

USINA_STORE_BACKENDS(StoreSheets);

}  // namespace
}  // namespace usina::dnc
