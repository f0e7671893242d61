// The audit chain and the blobs' hashes against someone who edits the
// database directly (the triggers dropped first, as they would be).
#include "dnc/store_audit.hpp"

#include <gtest/gtest.h>

#include "dnc/store_import.hpp"
#include "dnc/store_revisions.hpp"
#include "store_fixture.hpp"

namespace usina::dnc {
namespace {

constexpr char kProgram[] = "G21 G90\nG0 X0 Y0 Z5\nG1 Z-1 F100\nG1 X10 Y5\nM2\n";

class StoreAudit : public test::StoreTest {
 protected:
  // Three uploads and two state changes: five entries.
  std::string fill(Store& s) {
    std::string hash;
    for (int i = 0; i < 3; ++i) {
      now_us += 1000;
      const std::string text = std::string(kProgram) + "(" + std::to_string(i) + ")\n";
      hash = put_revision(s, {"O1000", "", "rs274ngc", text, "rev", nullptr}, {"ana", "10.1.1.1"})
                 .value()
                 .revision.hash;
    }
    change_state(s, "O1000", hash, RevisionState::Checked, "looked fine", {"bruno", "10.1.1.2"})
        .value();
    change_state(s, "O1000", hash, RevisionState::Approved, "ok", {"carla", "10.1.1.3"}).value();
    return hash;
  }
};

TEST_P(StoreAudit, EveryChangeIsAnEntryThatSaysWhoWhatWhenWhyAndFromWhere) {
  auto s = open();
  ASSERT_TRUE(s);
  const std::string hash = fill(*s);
  const auto entries = read_audit(*s, 0, 100).value();
  ASSERT_EQ(entries.size(), 5u);
  const AuditEntry& e = entries[3];
  EXPECT_EQ(e.seq, 4);
  EXPECT_EQ(e.actor, "bruno");
  EXPECT_EQ(e.origin, "10.1.1.2");
  EXPECT_EQ(e.action, "revision.state");
  EXPECT_EQ(e.subject, "O1000@" + hash);
  EXPECT_EQ(e.reason, "looked fine");
  EXPECT_EQ(e.at_us, now_us);
  EXPECT_NE(e.detail.find("\"to\":\"checked\""), std::string::npos) << e.detail;
  EXPECT_EQ(e.prev_hash, entries[2].hash);
  EXPECT_EQ(entries[0].prev_hash, std::string(64, '0'));
  const auto v = verify_audit(*s).value();
  EXPECT_TRUE(v.ok) << v.problem;
  EXPECT_EQ(v.entries, 5);
  EXPECT_EQ(v.head, entries[4].hash);
}

TEST_P(StoreAudit, TheDatabaseRefusesToRewriteOrDeleteAnEntry) {
  auto s = open();
  ASSERT_TRUE(s);
  fill(*s);
  auto db = raw();
  EXPECT_FALSE(db->query("UPDATE audit SET actor = 'mallory' WHERE seq = 2"));
  EXPECT_FALSE(db->query("DELETE FROM audit WHERE seq = 5"));
  EXPECT_TRUE(verify_audit(*s).value().ok);
}

TEST_P(StoreAudit, AnAlteredEntryBreaksTheChainThere) {
  auto s = open();
  ASSERT_TRUE(s);
  fill(*s);
  auto db = raw();
  drop_trigger(*db, "audit_no_update", "audit");
  ASSERT_TRUE(db->query("UPDATE audit SET reason = 'nothing to see' WHERE seq = 4"));
  const auto v = verify_audit(*s).value();
  EXPECT_FALSE(v.ok);
  EXPECT_EQ(v.first_bad, 4);
  EXPECT_NE(v.problem.find("entry 4 was altered"), std::string::npos) << v.problem;
}

TEST_P(StoreAudit, ARehashedEntryBreaksTheLinkAfterIt) {
  auto s = open();
  ASSERT_TRUE(s);
  fill(*s);
  // The forger fixes entry 2's own hash too; entry 3 still points at the old one.
  auto entries = read_audit(*s, 0, 100).value();
  AuditEntry forged = entries[1];
  forged.actor = "mallory";
  forged.hash = audit_hash(forged);
  auto db = raw();
  drop_trigger(*db, "audit_no_update", "audit");
  ASSERT_TRUE(db->query("UPDATE audit SET actor = $1, hash = $2 WHERE seq = 2",
                        {std::string_view(forged.actor), std::string_view(forged.hash)}));
  const auto v = verify_audit(*s).value();
  EXPECT_FALSE(v.ok);
  EXPECT_EQ(v.first_bad, 3);
  EXPECT_NE(v.problem.find("points back"), std::string::npos) << v.problem;
}

TEST_P(StoreAudit, ADeletedEntryIsFound) {
  auto s = open();
  ASSERT_TRUE(s);
  fill(*s);
  auto db = raw();
  drop_trigger(*db, "audit_no_update", "audit");
  if (GetParam() == Backend::Sqlite) drop_trigger(*db, "audit_no_delete", "audit");
  ASSERT_TRUE(db->query("DELETE FROM audit WHERE seq = 3"));
  const auto v = verify_audit(*s).value();
  EXPECT_FALSE(v.ok);
  EXPECT_EQ(v.first_bad, 4);
  EXPECT_NE(v.problem.find("missing"), std::string::npos) << v.problem;
}

TEST_P(StoreAudit, EntriesCutOffTheEndAreFoundAgainstAKeptHead) {
  auto s = open();
  ASSERT_TRUE(s);
  fill(*s);
  const std::string head = verify_audit(*s).value().head;
  auto db = raw();
  drop_trigger(*db, "audit_no_update", "audit");
  if (GetParam() == Backend::Sqlite) drop_trigger(*db, "audit_no_delete", "audit");
  ASSERT_TRUE(db->query("DELETE FROM audit WHERE seq >= 4"));
  EXPECT_TRUE(verify_audit(*s).value().ok);  // a shorter chain holds by itself
  const auto v = verify_audit(*s, head).value();
  EXPECT_FALSE(v.ok);
  EXPECT_NE(v.problem.find("cut off"), std::string::npos) << v.problem;
}

TEST_P(StoreAudit, ATamperedBlobIsFoundOnRead) {
  auto s = open();
  ASSERT_TRUE(s);
  auto put = put_revision(*s, {"O1000", "", "rs274ngc", kProgram, "r", nullptr}, {"ana", "t"});
  ASSERT_TRUE(put);
  const std::string hash = put->revision.hash;
  ASSERT_TRUE(revision_bytes(*s, "O1000", hash));
  auto db = raw();
  drop_trigger(*db, "blobs_no_update", "blobs");
  std::string evil = kProgram;
  evil[evil.find("Z-1")] = 'X';
  ASSERT_TRUE(db->query("UPDATE blobs SET bytes = $1 WHERE hash = $2",
                        {SqlBlob{evil}, std::string_view(hash)}));
  auto read = revision_bytes(*s, "O1000", hash);
  ASSERT_FALSE(read);
  EXPECT_EQ(read.error().kind, StoreErrorKind::Damaged);
  EXPECT_NE(read.error().message.find("damaged"), std::string::npos) << read.error().message;
  // Nor does a damaged revision leave the store by an export.
  for (const RevisionState to :
       {RevisionState::Checked, RevisionState::Approved, RevisionState::Released})
    ASSERT_TRUE(change_state(*s, "O1000", hash, to, "", {"boss", "t"}));
  auto out = export_released(*s, tmp_.path + "/out", ".nc", {"ana", "t"});
  ASSERT_FALSE(out);
  EXPECT_EQ(out.error().kind, StoreErrorKind::Damaged);
}

TEST_P(StoreAudit, AShortenedBlobIsFoundOnRead) {
  auto s = open();
  ASSERT_TRUE(s);
  auto put = put_revision(*s, {"O1000", "", "rs274ngc", kProgram, "r", nullptr}, {"ana", "t"});
  ASSERT_TRUE(put);
  auto db = raw();
  drop_trigger(*db, "blobs_no_update", "blobs");
  ASSERT_TRUE(db->query("UPDATE blobs SET bytes = $1", {SqlBlob{std::string_view(kProgram, 10)}}));
  auto read = revision_bytes(*s, "O1000", put->revision.hash);
  ASSERT_FALSE(read);
  EXPECT_EQ(read.error().kind, StoreErrorKind::Damaged);
}

USINA_STORE_BACKENDS(StoreAudit);

}  // namespace
}  // namespace usina::dnc
