// Who may call what: every route of the API walked without a token, with a
// token that is no session, and with each role that may not (401, 403);
// logins limited.
#include <gtest/gtest.h>

#include "dnc/api_router.hpp"
#include "server_fixture.hpp"

namespace usina::dnc {
namespace {

using test::ApiClient;
using test::RunningServer;

// The route's pattern with a name in each {} (the role is checked before
// any name is looked up).
std::string target_of(const ApiRoute& r) {
  std::string t(r.pattern);
  for (std::size_t at = t.find("{}"); at != std::string::npos; at = t.find("{}"))
    t.replace(at, 2, "1");
  return t;
}

test::Reply call(const ApiClient& c, const ApiRoute& r, const std::string& token) {
  return c.call(r.method == http::verb::get ? test::bhttp::verb::get : test::bhttp::verb::post,
                target_of(r), "{}", token);
}

TEST(ApiAccess, EveryRouteButLoginIs401WithoutAToken) {
  RunningServer s;
  s.start();
  const ApiClient c = s.client();
  std::size_t walked = 0;
  for (const ApiRoute& r : api_routes()) {
    if (r.access == Access::Public) continue;
    const test::Reply reply = call(c, r, "");
    EXPECT_EQ(reply.status, 401) << r.pattern << ": " << reply.body;
    EXPECT_TRUE(reply.json().contains("error")) << r.pattern;
    ++walked;
  }
  EXPECT_GE(walked, 15U);
}

TEST(ApiAccess, EveryRouteIs401WithATokenThatIsNoSession) {
  RunningServer s;
  s.start();
  const ApiClient c = s.client();
  const std::string forged(64, 'a');
  for (const ApiRoute& r : api_routes()) {
    if (r.access == Access::Public) continue;
    EXPECT_EQ(call(c, r, forged).status, 401) << r.pattern;
  }
}

TEST(ApiAccess, EveryRouteIs403ForEachRoleThatMayNot) {
  RunningServer s;
  s.start();
  const ApiClient c = s.client();
  const std::pair<Role, std::string> users[] = {{Role::Operator, "oper"},
                                                {Role::Programmer, "prog"},
                                                {Role::Approver, "appr"},
                                                {Role::Admin, "boss"}};
  std::size_t refused = 0;
  for (const auto& [role, name] : users) {
    const std::string token = c.log_in(name, test::kPassword);
    ASSERT_FALSE(token.empty()) << name;
    for (const ApiRoute& r : api_routes()) {
      if (r.access != Access::Permission) continue;
      const int status = call(c, r, token).status;
      if (role_may(role, r.permission)) {
        EXPECT_NE(status, 403) << name << " " << r.pattern;
        EXPECT_NE(status, 401) << name << " " << r.pattern;
      } else {
        EXPECT_EQ(status, 403) << name << " " << r.pattern;
        ++refused;
      }
    }
  }
  EXPECT_GT(refused, 5U);  // operators upload nothing, read no audit, make no users...
}

TEST(ApiAccess, AWrongPasswordIs401AndTooManyFailuresAre429) {
  RunningServer s;
  s.start();
  const ApiClient c = s.client();
  EXPECT_EQ(c.post("/api/login", {{"user", "prog"}, {"password", "wrong password"}}).status, 401);
  EXPECT_EQ(c.post("/api/login", {{"user", "nobody"}, {"password", "wrong password"}}).status, 401);
  for (int i = 0; i < 4; ++i)
    c.post("/api/login", {{"user", "prog"}, {"password", "wrong password"}});
  const test::Reply locked =
      c.post("/api/login", {{"user", "prog"}, {"password", test::kPassword}});
  EXPECT_EQ(locked.status, 429) << locked.body;
  EXPECT_FALSE(locked.retry_after.empty());
  EXPECT_FALSE(c.log_in("appr", test::kPassword).empty());  // another user is not locked
}

TEST(ApiAccess, ALoginWithAMalformedBodyIs400) {
  RunningServer s;
  s.start();
  const ApiClient c = s.client();
  EXPECT_EQ(c.call(test::bhttp::verb::post, "/api/login", "{not json").status, 400);
  EXPECT_EQ(c.post("/api/login", {{"user", "prog"}}).status, 400);
  EXPECT_EQ(c.post("/api/login", {{"user", 5}, {"password", "x"}}).status, 400);
  EXPECT_EQ(c.call(test::bhttp::verb::post, "/api/login", "[1,2]").status, 400);
}

TEST(ApiAccess, AnAdminCreatesUsersAndTheyLogIn) {
  RunningServer s;
  s.start();
  const ApiClient c = s.client();
  const std::string boss = c.log_in("boss", test::kPassword);
  const test::Reply made = c.post(
      "/api/users", {{"name", "ana"}, {"role", "operator"}, {"password", "ana's long pass"}}, boss);
  EXPECT_EQ(made.status, 201) << made.body;
  const std::string ana = c.log_in("ana", "ana's long pass");
  ASSERT_FALSE(ana.empty());
  EXPECT_EQ(c.get("/api/session", ana).json()["role"], "operator");
  EXPECT_EQ(c.post("/api/logout", nlohmann::json::object(), ana).status, 200);
  EXPECT_EQ(c.get("/api/session", ana).status, 401);
}

TEST(ApiUsers, AnAdminListsAndChangesAccounts) {
  RunningServer s;
  s.start();
  const ApiClient c = s.client();
  const std::string boss = c.log_in("boss", test::kPassword);
  ASSERT_EQ(c.post("/api/users",
                   {{"name", "ana"}, {"role", "operator"}, {"password", "ana's long pass"}}, boss)
                .status,
            201);
  const test::Reply list = c.get("/api/users", boss);
  ASSERT_EQ(list.status, 200) << list.body;
  bool ana_listed = false;
  const nlohmann::json users = list.json();
  for (const auto& u : users["users"])
    ana_listed |= u["name"] == "ana" && u["role"] == "operator" && u["disabled"] == false &&
                  u["created_at_us"].get<std::int64_t>() > 0;
  EXPECT_TRUE(ana_listed) << list.body;
  EXPECT_EQ(c.get("/api/users", c.log_in("prog", test::kPassword)).status, 403);

  const test::Reply promoted = c.post("/api/users/ana", {{"role", "programmer"}}, boss);
  ASSERT_EQ(promoted.status, 200) << promoted.body;
  EXPECT_EQ(promoted.json()["role"], "programmer");
  const std::string ana = c.log_in("ana", "ana's long pass");
  EXPECT_EQ(c.get("/api/session", ana).json()["role"], "programmer");
  // Disabled: the session ends and no login opens another.
  EXPECT_EQ(c.post("/api/users/ana", {{"disabled", true}}, boss).json()["disabled"], true);
  EXPECT_EQ(c.get("/api/session", ana).status, 401);
  EXPECT_TRUE(c.log_in("ana", "ana's long pass").empty());
  // Enabled again with a new password.
  ASSERT_EQ(c.post("/api/users/ana", {{"disabled", false}, {"password", "a newer long pass"}}, boss)
                .status,
            200);
  EXPECT_TRUE(c.log_in("ana", "ana's long pass").empty());
  EXPECT_FALSE(c.log_in("ana", "a newer long pass").empty());
}

TEST(ApiUsers, ABadChangeIsRefusedAndChangesNothing) {
  RunningServer s;
  s.start();
  const ApiClient c = s.client();
  const std::string boss = c.log_in("boss", test::kPassword);
  EXPECT_EQ(c.post("/api/users/prog", nlohmann::json::object(), boss).status, 400);
  EXPECT_EQ(c.post("/api/users/prog", {{"role", "king"}}, boss).status, 400);
  EXPECT_EQ(c.post("/api/users/prog", {{"disabled", "yes"}}, boss).status, 400);
  EXPECT_EQ(c.post("/api/users/prog", {{"password", "short"}}, boss).status, 400);
  // Checked whole before anything is written: the role stays.
  EXPECT_EQ(c.post("/api/users/prog", {{"role", "admin"}, {"colour", "red"}}, boss).status, 400);
  EXPECT_EQ(c.post("/api/users/nobody", {{"role", "admin"}}, boss).status, 404);
  EXPECT_EQ(
      c.post("/api/users/prog", {{"role", "admin"}}, c.log_in("prog", test::kPassword)).status,
      403);
  EXPECT_EQ(c.get("/api/session", c.log_in("prog", test::kPassword)).json()["role"], "programmer");
  // boss is the only admin: 409, and boss stays one.
  const test::Reply last = c.post("/api/users/boss", {{"role", "operator"}}, boss);
  EXPECT_EQ(last.status, 409);
  EXPECT_NE(last.body.find("only enabled admin"), std::string::npos) << last.body;
  EXPECT_EQ(c.post("/api/users/boss", {{"disabled", true}}, boss).status, 409);
  EXPECT_EQ(c.get("/api/session", boss).json()["role"], "admin");
}

}  // namespace
}  // namespace usina::dnc
