// Accounts, argon2id, sessions with expiry, login limits, the first admin.
#include "dnc/store_users.hpp"

#include <gtest/gtest.h>

#include "dnc/sha256.hpp"
#include "dnc/store_audit.hpp"
#include "store_fixture.hpp"

namespace usina::dnc {
namespace {

constexpr std::int64_t kSecond = 1'000'000;

class StoreUsers : public test::StoreTest {
 protected:
  std::unique_ptr<Store> with_admin() {
    auto s = open();
    if (s) {
      EXPECT_TRUE(create_first_admin(*s, "root", "correct horse"));
    }
    return s;
  }
};

TEST_P(StoreUsers, PasswordsAreKeptOnlyAsArgon2idHashes) {
  auto s = with_admin();
  ASSERT_TRUE(s);
  auto rows = raw()->query("SELECT password_hash FROM users WHERE name = 'root'").value();
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_TRUE(rows[0].text(0).starts_with("$argon2id$")) << rows[0].text(0);
  EXPECT_EQ(rows[0].text(0).find("correct horse"), std::string::npos);
}

TEST_P(StoreUsers, LoggingInGivesATokenWhoseHashAloneIsKept) {
  auto s = with_admin();
  ASSERT_TRUE(s);
  auto session = log_in(*s, "root", "correct horse", "127.0.0.1");
  ASSERT_TRUE(session) << session.error().message;
  EXPECT_TRUE(is_sha256_hex(session->token));
  EXPECT_EQ(session->user.role, Role::Admin);
  EXPECT_EQ(session->expires_at_us, now_us + s->options().session_seconds * kSecond);
  auto rows = raw()->query("SELECT token_hash FROM sessions").value();
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].text(0), sha256_hex(session->token));
  auto who = verify_session(*s, session->token);
  ASSERT_TRUE(who);
  EXPECT_EQ(who->user.name, "root");
  EXPECT_FALSE(verify_session(*s, rows[0].text(0)));  // the stored hash opens nothing
}

TEST_P(StoreUsers, AWrongPasswordAndAnUnknownUserGetTheSameAnswer) {
  auto s = with_admin();
  ASSERT_TRUE(s);
  auto a = log_in(*s, "root", "wrong horse", "127.0.0.1");
  auto b = log_in(*s, "nobody", "wrong horse", "127.0.0.1");
  auto c = log_in(*s, "../etc", "wrong horse", "127.0.0.1");
  ASSERT_FALSE(a);
  ASSERT_FALSE(b);
  ASSERT_FALSE(c);
  EXPECT_EQ(a.error().message, b.error().message);
  EXPECT_EQ(a.error().message, c.error().message);
  EXPECT_EQ(a.error().kind, StoreErrorKind::Refused);
  const auto audit = read_audit(*s, 0, 100).value();
  EXPECT_EQ(audit.back().action, "login.failed");
  EXPECT_EQ(audit.back().origin, "127.0.0.1");
}

TEST_P(StoreUsers, SessionsExpire) {
  auto s = with_admin();
  ASSERT_TRUE(s);
  const auto session = log_in(*s, "root", "correct horse", "t").value();
  now_us += s->options().session_seconds * kSecond - 1;
  EXPECT_TRUE(verify_session(*s, session.token));
  now_us += 1;
  auto r = verify_session(*s, session.token);
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find("expired"), std::string::npos);
  EXPECT_GE(purge_expired(*s).value(), 1);
  EXPECT_TRUE(raw()->query("SELECT token_hash FROM sessions").value().empty());
}

TEST_P(StoreUsers, LoggingOutEndsTheSession) {
  auto s = with_admin();
  ASSERT_TRUE(s);
  const auto session = log_in(*s, "root", "correct horse", "t").value();
  ASSERT_TRUE(log_out(*s, session.token));
  EXPECT_FALSE(verify_session(*s, session.token));
}

TEST_P(StoreUsers, TooManyFailuresLockTheUserUntilTheWindowPasses) {
  auto s = with_admin();
  ASSERT_TRUE(s);
  const int limit = s->options().max_failures_per_user;
  for (int i = 0; i < limit; ++i) {
    now_us += kSecond;
    ASSERT_FALSE(log_in(*s, "root", "wrong horse", "10.0.0." + std::to_string(i)));
  }
  // Even the right password is refused now, from anywhere.
  auto locked = log_in(*s, "root", "correct horse", "10.9.9.9");
  ASSERT_FALSE(locked);
  EXPECT_NE(locked.error().message.find("too many failed logins"), std::string::npos)
      << locked.error().message;
  EXPECT_EQ(login_wait_seconds(*s, "root", "10.9.9.9").value(),
            s->options().failure_window_seconds);
  now_us += s->options().failure_window_seconds * kSecond;
  EXPECT_TRUE(log_in(*s, "root", "correct horse", "10.9.9.9"));
}

TEST_P(StoreUsers, TooManyFailuresFromOneOriginLockThatOrigin) {
  auto s = with_admin();
  ASSERT_TRUE(s);
  for (int i = 0; i < s->options().max_failures_per_origin; ++i)
    ASSERT_FALSE(log_in(*s, "user" + std::to_string(i), "wrong horse", "10.6.6.6"));
  EXPECT_FALSE(log_in(*s, "root", "correct horse", "10.6.6.6"));
  EXPECT_TRUE(log_in(*s, "root", "correct horse", "10.1.1.1"));
}

TEST_P(StoreUsers, ADisabledUserCannotLogInAndLosesTheirSessions) {
  auto s = with_admin();
  ASSERT_TRUE(s);
  ASSERT_TRUE(create_user(*s, "ana", Role::Operator, "ana's secret", {"root", "t"}));
  const auto session = log_in(*s, "ana", "ana's secret", "t").value();
  ASSERT_TRUE(set_disabled(*s, "ana", true, {"root", "t"}));
  EXPECT_FALSE(verify_session(*s, session.token));
  EXPECT_FALSE(log_in(*s, "ana", "ana's secret", "t"));
  ASSERT_TRUE(set_disabled(*s, "ana", false, {"root", "t"}));
  EXPECT_TRUE(log_in(*s, "ana", "ana's secret", "t"));
}

TEST_P(StoreUsers, ANewPasswordEndsTheOldSessions) {
  auto s = with_admin();
  ASSERT_TRUE(s);
  const auto session = log_in(*s, "root", "correct horse", "t").value();
  ASSERT_TRUE(set_password(*s, "root", "battery staple", {"root", "t"}));
  EXPECT_FALSE(verify_session(*s, session.token));
  EXPECT_FALSE(log_in(*s, "root", "correct horse", "t"));
  EXPECT_TRUE(log_in(*s, "root", "battery staple", "t"));
}

TEST_P(StoreUsers, TheFirstAdminIsMadeOnlyOnce) {
  auto s = with_admin();
  ASSERT_TRUE(s);
  auto again = create_first_admin(*s, "other", "another password");
  ASSERT_FALSE(again);
  EXPECT_EQ(again.error().kind, StoreErrorKind::Conflict);
  EXPECT_FALSE(find_user(*s, "other"));
  EXPECT_EQ(find_user(*s, "root").value().role, Role::Admin);
}

TEST_P(StoreUsers, ShortPasswordsBadNamesAndDuplicatesAreRefused) {
  auto s = with_admin();
  ASSERT_TRUE(s);
  EXPECT_FALSE(create_user(*s, "ana", Role::Operator, "short", {"root", "t"}));
  EXPECT_FALSE(create_user(*s, "a/b", Role::Operator, "long enough", {"root", "t"}));
  ASSERT_TRUE(create_user(*s, "ana", Role::Operator, "long enough", {"root", "t"}));
  auto dup = create_user(*s, "ana", Role::Admin, "long enough", {"root", "t"});
  ASSERT_FALSE(dup);
  EXPECT_EQ(dup.error().kind, StoreErrorKind::Conflict);
  EXPECT_EQ(find_user(*s, "ana").value().role, Role::Operator);
}

TEST_P(StoreUsers, ATokenThatIsNotOneIsNoSession) {
  auto s = with_admin();
  ASSERT_TRUE(s);
  for (const std::string& t : {std::string(""), std::string("x"), std::string(64, 'g'),
                               std::string(64, 'a'), std::string("' OR 1=1 --")})
    EXPECT_FALSE(verify_session(*s, t)) << t;
}

TEST_P(StoreUsers, ARoleChangesAndIsAudited) {
  auto s = with_admin();
  ASSERT_TRUE(s);
  ASSERT_TRUE(create_user(*s, "ana", Role::Operator, "long enough", {"root", "t"}));
  ASSERT_TRUE(set_role(*s, "ana", Role::Programmer, {"root", "t"}));
  EXPECT_EQ(find_user(*s, "ana").value().role, Role::Programmer);
  const auto audit = read_audit(*s, 0, 100).value();
  EXPECT_EQ(audit.back().action, "user.role");
  EXPECT_EQ(audit.back().subject, "ana");
  EXPECT_NE(audit.back().detail.find(R"("from":"operator","to":"programmer")"), std::string::npos)
      << audit.back().detail;
  EXPECT_EQ(set_role(*s, "nobody", Role::Admin, {"root", "t"}).error().kind,
            StoreErrorKind::NotFound);
}

// Nobody could make users or import programs again: the last enabled admin
// stays an admin and enabled until another is made.
TEST_P(StoreUsers, TheLastEnabledAdminCannotBeDemotedOrDisabled) {
  auto s = with_admin();
  ASSERT_TRUE(s);
  auto demote = set_role(*s, "root", Role::Operator, {"root", "t"});
  ASSERT_FALSE(demote);
  EXPECT_EQ(demote.error().kind, StoreErrorKind::Refused);
  EXPECT_NE(demote.error().message.find("only enabled admin"), std::string::npos);
  EXPECT_EQ(set_disabled(*s, "root", true, {"root", "t"}).error().kind, StoreErrorKind::Refused);
  ASSERT_TRUE(create_user(*s, "ana", Role::Admin, "long enough", {"root", "t"}));
  ASSERT_TRUE(set_disabled(*s, "ana", true, {"root", "t"}));
  EXPECT_FALSE(set_role(*s, "root", Role::Operator, {"root", "t"}));  // ana is disabled
  ASSERT_TRUE(set_disabled(*s, "ana", false, {"root", "t"}));
  ASSERT_TRUE(set_role(*s, "root", Role::Operator, {"ana", "t"}));
  EXPECT_EQ(find_user(*s, "root").value().role, Role::Operator);
  EXPECT_FALSE(set_disabled(*s, "ana", true, {"ana", "t"}));
}

TEST_P(StoreUsers, UsersAreListedByName) {
  auto s = with_admin();
  ASSERT_TRUE(s);
  ASSERT_TRUE(create_user(*s, "zeca", Role::Approver, "long enough", {"root", "t"}));
  ASSERT_TRUE(create_user(*s, "ana", Role::Operator, "long enough", {"root", "t"}));
  ASSERT_TRUE(set_disabled(*s, "ana", true, {"root", "t"}));
  const auto users = list_users(*s).value();
  ASSERT_EQ(users.size(), 3u);
  EXPECT_EQ(users[0].name, "ana");
  EXPECT_TRUE(users[0].disabled);
  EXPECT_EQ(users[1].name, "root");
  EXPECT_EQ(users[1].role, Role::Admin);
  EXPECT_EQ(users[2].name, "zeca");
  EXPECT_EQ(users[2].role, Role::Approver);
  EXPECT_FALSE(users[2].disabled);
}

USINA_STORE_BACKENDS(StoreUsers);

}  // namespace
}  // namespace usina::dnc
