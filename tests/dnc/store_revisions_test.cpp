// Programs and revisions on both back ends: addresses, immutability, names,
// sizes, dialects, listings.
#include "dnc/store_revisions.hpp"

#include <string>

#include <gtest/gtest.h>

#include "dnc/sha256.hpp"
#include "dnc/store_names.hpp"
#include "sim/machine_profile.hpp"
#include "store_fixture.hpp"

namespace usina::dnc {
namespace {

constexpr char kProgram[] = "G21 G90\nG0 X0 Y0 Z5\nG1 Z-1 F100\nG1 X10 Y5\nM2\n";

class StoreRevisions : public test::StoreTest {};

RevisionQuery of(std::string program, std::optional<RevisionState> state = std::nullopt) {
  RevisionQuery q;
  q.program = std::move(program);
  q.state = state;
  return q;
}

Upload upload(std::string name, std::string text, std::string dialect = "rs274ngc") {
  return {std::move(name), "", std::move(dialect), std::move(text), "first cut", nullptr};
}

TEST_P(StoreRevisions, ARevisionIsTheSha256OfItsBytesAndKeepsWhoWhenWhy) {
  auto s = open();
  ASSERT_TRUE(s);
  auto put = put_revision(*s, upload("O1000", kProgram), {"ana", "10.0.0.7"});
  ASSERT_TRUE(put) << put.error().message;
  EXPECT_TRUE(put->created);
  const Revision& v = put->revision;
  EXPECT_EQ(v.hash, sha256_hex(kProgram));
  EXPECT_EQ(v.size, static_cast<std::int64_t>(std::string(kProgram).size()));
  EXPECT_EQ(v.author, "ana");
  EXPECT_EQ(v.reason, "first cut");
  EXPECT_EQ(v.dialect, "rs274ngc");
  EXPECT_EQ(v.created_at_us, now_us);
  EXPECT_EQ(v.state, RevisionState::Draft);
  auto again = find_revision(*s, "O1000", v.hash);
  ASSERT_TRUE(again);
  EXPECT_EQ(again->author, "ana");
  EXPECT_EQ(again->checks_json, v.checks_json);
  EXPECT_EQ(revision_bytes(*s, "O1000", v.hash).value(), kProgram);
}

TEST_P(StoreRevisions, TheSameBytesAgainAreTheSameRevision) {
  auto s = open();
  ASSERT_TRUE(s);
  auto first = put_revision(*s, upload("O1000", kProgram), {"ana", "t"});
  auto second = put_revision(*s, upload("O1000", kProgram), {"bruno", "t"});
  ASSERT_TRUE(first && second);
  EXPECT_FALSE(second->created);
  EXPECT_EQ(second->revision.author, "ana");
  EXPECT_EQ(list_revisions(*s, of("O1000")).value().size(), 1u);
}

TEST_P(StoreRevisions, ChecksAreRecordedWithCycleTimeAndBounds) {
  auto s = open();
  ASSERT_TRUE(s);
  auto put = put_revision(*s, upload("O1000", kProgram), {"ana", "t"});
  ASSERT_TRUE(put);
  const auto checks = CheckResults::from_json(put->revision.checks_json);
  ASSERT_TRUE(checks);
  EXPECT_TRUE(checks->complete);
  EXPECT_EQ(checks->errors, 0u);
  EXPECT_GT(checks->cycle_time_s, 0.0);
  ASSERT_TRUE(checks->bounds);
  EXPECT_DOUBLE_EQ((*checks->bounds)[3], 10.0);  // X max
  EXPECT_DOUBLE_EQ((*checks->bounds)[2], -1.0);  // Z min
}

TEST_P(StoreRevisions, AMovePastTheMachinesTravelFailsTheCheck) {
  auto s = open();
  ASSERT_TRUE(s);
  core::DiagnosticList diags;
  const auto profile = sim::read_machine_profile(
      "[machine]\nname = \"small\"\n"
      "[axes.x]\nmin = 0.0\nmax = 5.0\nrapid = 5000.0\nmax_feed = 3000.0\naccel = 250.0\n"
      "[axes.y]\nmin = 0.0\nmax = 500.0\nrapid = 5000.0\nmax_feed = 3000.0\naccel = 250.0\n"
      "[axes.z]\nmin = -100.0\nmax = 100.0\nrapid = 5000.0\nmax_feed = 3000.0\naccel = 250.0\n",
      0, diags);
  for (const auto& d : diags.all())
    ADD_FAILURE() << d.message;
  ASSERT_TRUE(profile);
  Upload u = upload("O1000", kProgram);
  u.profile = &*profile;
  auto put = put_revision(*s, u, {"ana", "t"});
  ASSERT_TRUE(put);
  EXPECT_EQ(put->revision.state, RevisionState::CheckFailed);
  const auto checks = CheckResults::from_json(put->revision.checks_json);
  EXPECT_GT(checks->overtravel, 0u);
  EXPECT_EQ(checks->machine, "small");
}

TEST_P(StoreRevisions, TheDialectIsGuessedWhenNotGiven) {
  auto s = open();
  ASSERT_TRUE(s);
  auto put = put_revision(*s, upload("O2000", "%\nO2000\nG90 G0 X1 Y1\nG1 X5 F100\nM30\n%\n", ""),
                          {"ana", "t"});
  ASSERT_TRUE(put) << put.error().message;
  EXPECT_EQ(put->revision.dialect, "fanuc");
  EXPECT_EQ(find_program(*s, "O2000").value().dialect, "fanuc");
}

TEST_P(StoreRevisions, NamesThatArePathsAreRefused) {
  auto s = open();
  ASSERT_TRUE(s);
  for (const std::string& bad :
       {std::string("../x"), std::string("/etc/passwd"), std::string("a/b"), std::string("a\0b", 3),
        std::string(""), std::string(".hidden"), std::string("-rf"), std::string("a b"),
        std::string(65, 'a'), std::string("caf\xc3\xa9")}) {
    auto put = put_revision(*s, upload(bad, kProgram), {"ana", "t"});
    ASSERT_FALSE(put) << "accepted '" << bad << "'";
    EXPECT_EQ(put.error().kind, StoreErrorKind::Invalid) << put.error().message;
  }
  EXPECT_TRUE(list_programs(*s).value().empty());
  EXPECT_TRUE(put_revision(*s, upload("O1000.v2_a+b-c", kProgram), {"ana", "t"}));
}

TEST_P(StoreRevisions, UnknownDialectAndBadUserAndBadReasonAreRefused) {
  auto s = open();
  ASSERT_TRUE(s);
  EXPECT_FALSE(put_revision(*s, upload("A", kProgram, "heidenhain"), {"ana", "t"}));
  EXPECT_FALSE(put_revision(*s, upload("A", kProgram), {"../ana", "t"}));
  Upload u = upload("A", kProgram);
  u.reason = std::string("bad\x01", 4);
  EXPECT_FALSE(put_revision(*s, u, {"ana", "t"}));
  u.reason = "not utf-8 \xff";
  EXPECT_FALSE(put_revision(*s, u, {"ana", "t"}));
  u.reason = std::string(kMaxReasonBytes + 1, 'r');
  auto r = put_revision(*s, u, {"ana", "t"});
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().kind, StoreErrorKind::TooLarge);
}

TEST_P(StoreRevisions, AProgramPastTheSizeLimitIsRefused) {
  StoreOptions o = options();
  o.max_program_bytes = 100;
  auto s = open(o);
  ASSERT_TRUE(s);
  auto r = put_revision(*s, upload("BIG", std::string(101, '\n')), {"ana", "t"});
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().kind, StoreErrorKind::TooLarge);
  EXPECT_NE(r.error().message.find("101 bytes"), std::string::npos);
  EXPECT_TRUE(put_revision(*s, upload("BIG", std::string(100, '\n')), {"ana", "t"}));
}

TEST_P(StoreRevisions, AProgramKeepsItsMachineClass) {
  auto s = open();
  ASSERT_TRUE(s);
  Upload u = upload("O1000", kProgram);
  u.machine_class = "mill-3ax";
  ASSERT_TRUE(put_revision(*s, u, {"ana", "t"}));
  u.machine_class = "lathe";
  u.text += "(v2)\n";
  auto r = put_revision(*s, u, {"ana", "t"});
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().kind, StoreErrorKind::Conflict);
  u.machine_class = "";  // the program's
  EXPECT_TRUE(put_revision(*s, u, {"ana", "t"}));
  EXPECT_EQ(find_program(*s, "O1000").value().machine_class, "mill-3ax");
}

TEST_P(StoreRevisions, RevisionsAreListedNewestFirstAndFiltered) {
  auto s = open();
  ASSERT_TRUE(s);
  std::vector<std::string> hashes;
  for (int i = 0; i < 5; ++i) {
    now_us += 1000;
    auto put = put_revision(
        *s, upload("O1000", std::string(kProgram) + "(" + std::to_string(i) + ")\n"), {"ana", "t"});
    ASSERT_TRUE(put);
    hashes.push_back(put->revision.hash);
  }
  ASSERT_TRUE(put_revision(*s, upload("O2000", kProgram), {"ana", "t"}));
  const auto all = list_revisions(*s, of("O1000")).value();
  ASSERT_EQ(all.size(), 5u);
  for (std::size_t i = 0; i < 5; ++i)
    EXPECT_EQ(all[i].hash, hashes[4 - i]);
  EXPECT_EQ(list_revisions(*s, {}).value().size(), 6u);
  RevisionQuery page{"O1000", std::nullopt, 2, 1};
  const auto two = list_revisions(*s, page).value();
  ASSERT_EQ(two.size(), 2u);
  EXPECT_EQ(two[0].hash, hashes[3]);
  ASSERT_TRUE(change_state(*s, "O1000", hashes[0], RevisionState::Checked, "", {"b", "t"}));
  const auto checked = list_revisions(*s, of("", RevisionState::Checked)).value();
  ASSERT_EQ(checked.size(), 1u);
  EXPECT_EQ(checked[0].hash, hashes[0]);
  EXPECT_EQ(list_programs(*s).value().size(), 2u);
}

TEST_P(StoreRevisions, TheDatabaseRefusesToRewriteARevision) {
  auto s = open();
  ASSERT_TRUE(s);
  auto put = put_revision(*s, upload("O1000", kProgram), {"ana", "t"});
  ASSERT_TRUE(put);
  auto db = raw();
  EXPECT_FALSE(db->query("UPDATE revisions SET author = 'mallory'"));
  EXPECT_FALSE(db->query("DELETE FROM revisions"));
  EXPECT_FALSE(db->query("UPDATE blobs SET size = 1"));
  EXPECT_EQ(find_revision(*s, "O1000", put->revision.hash).value().author, "ana");
}

TEST_P(StoreRevisions, AnEmptyProgramIsARevisionToo) {
  auto s = open();
  ASSERT_TRUE(s);
  auto put = put_revision(*s, upload("EMPTY", ""), {"ana", "t"});
  ASSERT_TRUE(put) << put.error().message;
  EXPECT_EQ(put->revision.hash, sha256_hex(""));
  EXPECT_EQ(revision_bytes(*s, "EMPTY", put->revision.hash).value(), "");
}

TEST_P(StoreRevisions, BinaryBytesSurviveTheRoundTrip) {
  auto s = open();
  ASSERT_TRUE(s);
  std::string bytes;
  for (int i = 0; i < 256; ++i)
    bytes += static_cast<char>(i);
  auto put = put_revision(*s, upload("BIN", bytes), {"ana", "t"});
  ASSERT_TRUE(put) << put.error().message;
  EXPECT_EQ(revision_bytes(*s, "BIN", put->revision.hash).value(), bytes);
}

TEST_P(StoreRevisions, ReopeningKeepsEverything) {
  std::string hash;
  {
    auto s = open();
    ASSERT_TRUE(s);
    hash = put_revision(*s, upload("O1000", kProgram), {"ana", "t"}).value().revision.hash;
  }
  auto s = open();
  ASSERT_TRUE(s);
  EXPECT_EQ(revision_bytes(*s, "O1000", hash).value(), kProgram);
}

USINA_STORE_BACKENDS(StoreRevisions);

}  // namespace
}  // namespace usina::dnc
