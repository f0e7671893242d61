// Every move between two states tried on a stored revision, on both back
// ends: the legal ones happen (with an audit entry), the others are refused
// and change nothing.
#include <vector>

#include <gtest/gtest.h>

#include "dnc/store_audit.hpp"
#include "dnc/store_revisions.hpp"
#include "store_fixture.hpp"

namespace usina::dnc {
namespace {

using S = RevisionState;

constexpr char kGood[] = "G21 G90\nG0 X0 Y0 Z5\nG1 Z-1 F100\nG1 X10\nM2\n";
constexpr char kBad[] = "G21 G90\nG1 X10 F100\nG2 X20 Y0 R1\nM2\n";  // arc radius too small

class StoreTransitions : public test::StoreTest {
 protected:
  // A revision of a new program brought to `state` by legal moves.
  Revision reach(Store& s, S state, int n) {
    const bool bad = state == S::CheckFailed;
    Upload u{"P" + std::to_string(n), "", "rs274ngc", bad ? kBad : kGood, "test", nullptr};
    auto put = put_revision(s, u, {"prog", "test"});
    EXPECT_TRUE(put) << (put ? "" : put.error().message);
    Revision v = put->revision;
    std::vector<S> path;
    if (state == S::Checked) path = {S::Checked};
    if (state == S::Approved) path = {S::Checked, S::Approved};
    if (state == S::Released) path = {S::Checked, S::Approved, S::Released};
    if (state == S::Rejected) path = {S::Rejected};
    for (const S next : path) {
      auto r = change_state(s, v.program, v.hash, next, "on the way", {"boss", "test"});
      EXPECT_TRUE(r) << (r ? "" : r.error().message);
      v = *r;
    }
    EXPECT_EQ(v.state, state);
    return v;
  }
};

TEST_P(StoreTransitions, EveryIllegalMoveIsRefusedAndEveryLegalOneMade) {
  auto s = open();
  ASSERT_TRUE(s);
  int n = 0;
  for (const S from : all_states()) {
    for (const S to : all_states()) {
      const Revision v = reach(*s, from, ++n);
      const auto before = verify_audit(*s);
      ASSERT_TRUE(before);
      auto r = change_state(*s, v.program, v.hash, to, "tried", {"boss", "test"});
      const auto after = find_revision(*s, v.program, v.hash);
      ASSERT_TRUE(after);
      const auto audit = verify_audit(*s);
      ASSERT_TRUE(audit && audit->ok);
      // draft -> check-failed needs a failed check; this draft's check was clean.
      const bool legal = transition_exists(from, to) && !(from == S::Draft && to == S::CheckFailed);
      if (legal) {
        EXPECT_TRUE(r) << state_name(from) << " -> " << state_name(to);
        EXPECT_EQ(after->state, to);
        EXPECT_EQ(audit->entries, before->entries + 1);
      } else {
        ASSERT_FALSE(r) << state_name(from) << " -> " << state_name(to) << " was allowed";
        EXPECT_EQ(r.error().kind, StoreErrorKind::Refused);
        EXPECT_EQ(after->state, from);
        EXPECT_EQ(audit->entries, before->entries);
      }
    }
  }
}

TEST_P(StoreTransitions, AFailedCheckCannotBecomeCheckedAndACleanOneCannotFail) {
  auto s = open();
  ASSERT_TRUE(s);
  auto bad = put_revision(*s, {"BAD", "", "rs274ngc", kBad, "t", nullptr}, {"prog", "t"});
  ASSERT_TRUE(bad);
  EXPECT_EQ(bad->revision.state, S::CheckFailed);  // moved there by the upload itself
  auto good = put_revision(*s, {"GOOD", "", "rs274ngc", kGood, "t", nullptr}, {"prog", "t"});
  ASSERT_TRUE(good);
  EXPECT_EQ(good->revision.state, S::Draft);
  auto r = change_state(*s, "GOOD", good->revision.hash, S::CheckFailed, "t", {"a", "t"});
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find("found nothing"), std::string::npos) << r.error().message;
}

TEST_P(StoreTransitions, UnknownRevisionIsNotFound) {
  auto s = open();
  ASSERT_TRUE(s);
  auto r = change_state(*s, "NOPE", std::string(64, 'a'), S::Checked, "t", {"a", "t"});
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().kind, StoreErrorKind::NotFound);
}

TEST_P(StoreTransitions, ReleasedRevisionIsTheLastReleased) {
  auto s = open();
  ASSERT_TRUE(s);
  EXPECT_FALSE(released_revision(*s, "P1").value());
  const Revision first = reach(*s, S::Released, 1);
  const std::string v2 = std::string(kGood) + "(v2)\n";
  auto second = put_revision(*s, {"P1", "", "", v2, "v2", nullptr}, {"prog", "t"});
  ASSERT_TRUE(second);
  for (const S next : {S::Checked, S::Approved}) {
    ASSERT_TRUE(change_state(*s, "P1", second->revision.hash, next, "", {"boss", "t"}));
  }
  EXPECT_EQ(released_revision(*s, "P1").value()->hash, first.hash);
  now_us += 1'000'000;
  ASSERT_TRUE(change_state(*s, "P1", second->revision.hash, S::Released, "", {"boss", "t"}));
  EXPECT_EQ(released_revision(*s, "P1").value()->hash, second->revision.hash);
  // Withdrawing the newer one leaves the older released.
  now_us += 1'000'000;
  ASSERT_TRUE(change_state(*s, "P1", second->revision.hash, S::Rejected, "bad", {"boss", "t"}));
  EXPECT_EQ(released_revision(*s, "P1").value()->hash, first.hash);
}

USINA_STORE_BACKENDS(StoreTransitions);

}  // namespace
}  // namespace usina::dnc
