// Logging in and out. The store counts failed logins per user and per
// origin (the client's address) and refuses logins past its limits; the
// API says so with 429 and Retry-After, and a wrong user or password with
// 401 (the same answer for both).
#include <fmt/format.h>

#include "dnc/api_json.hpp"
#include "dnc/api_router.hpp"

namespace usina::dnc {

HttpResponse api_login(ApiCall& c) {
  auto body = json_body(c.req);
  if (!body) return error_response(c.req, http::status::bad_request, body.error());
  auto user = string_field(*body, "user", true);
  if (!user) return error_response(c.req, http::status::bad_request, user.error());
  auto password = string_field(*body, "password", true);
  if (!password) return error_response(c.req, http::status::bad_request, password.error());
  auto wait = login_wait_seconds(c.ctx.store, **user, c.origin);
  if (wait && *wait > 0) {
    HttpResponse res = error_response(
        c.req, http::status::too_many_requests,
        fmt::format("too many failed logins for this user or from this address; try again in "
                    "{} s",
                    *wait));
    res.set(http::field::retry_after, std::to_string(*wait));
    return res;
  }
  auto session = log_in(c.ctx.store, **user, **password, c.origin);
  if (!session) {
    const bool refused = session.error().kind == StoreErrorKind::Refused;
    return error_response(c.req, refused ? http::status::unauthorized : status_of(session.error()),
                          session.error().message);
  }
  return json_response(c.req, http::status::ok,
                       {{"token", session->token},
                        {"user", session->user.name},
                        {"role", role_name(session->user.role)},
                        {"expires_at_us", session->expires_at_us}});
}

HttpResponse api_logout(ApiCall& c) {
  if (auto r = log_out(c.ctx.store, bearer_token(c.req)); !r)
    return error_response(c.req, status_of(r.error()), r.error().message);
  return json_response(c.req, http::status::ok, {{"logged_out", true}});
}

HttpResponse api_session(ApiCall& c) {
  return json_response(c.req, http::status::ok,
                       {{"user", c.session->user.name},
                        {"role", role_name(c.session->user.role)},
                        {"expires_at_us", c.session->expires_at_us}});
}

}  // namespace usina::dnc

namespace usina::dnc {
namespace {

nlohmann::json user_json(const User& u) {
  return {{"name", u.name},
          {"role", role_name(u.role)},
          {"disabled", u.disabled},
          {"created_at_us", u.created_at_us}};
}

// What POST /api/users/{name} asks for, read and checked before anything is written.
struct UserChange {
  std::optional<Role> role;
  std::optional<bool> disabled;
  std::optional<std::string> password;
};

tl::expected<UserChange, std::string> user_change(const nlohmann::json& body) {
  UserChange change;
  for (const auto& [key, value] : body.items()) {
    if (key != "role" && key != "disabled" && key != "password")
      return tl::unexpected(
          fmt::format("unknown field \"{}\": give role, disabled or password", key));
  }
  auto role = string_field(body, "role", false);
  if (!role) return tl::unexpected(role.error());
  if (*role) {
    change.role = parse_role(**role);
    if (!change.role)
      return tl::unexpected(std::string("role must be operator, programmer, approver or admin"));
  }
  if (const auto it = body.find("disabled"); it != body.end()) {
    if (!it->is_boolean()) return tl::unexpected(std::string("disabled must be true or false"));
    change.disabled = it->get<bool>();
  }
  auto password = string_field(body, "password", false);
  if (!password) return tl::unexpected(password.error());
  change.password = std::move(*password);
  if (change.password) {
    if (auto ok = check_password(*change.password); !ok) return tl::unexpected(ok.error().message);
  }
  if (!change.role && !change.disabled && !change.password)
    return tl::unexpected(std::string("nothing to change: give role, disabled or password"));
  return change;
}

}  // namespace

// GET /api/users (admin): every account, by name.
HttpResponse api_list_users(ApiCall& c) {
  auto users = list_users(c.ctx.store);
  if (!users) return error_response(c.req, status_of(users.error()), users.error().message);
  nlohmann::json list = nlohmann::json::array();
  for (const User& u : *users)
    list.push_back(user_json(u));
  return json_response(c.req, http::status::ok, {{"users", std::move(list)}});
}

// POST /api/users/{name} {"role"?,"disabled"?,"password"?} (admin): each
// change its own audited write, in that order; the account as it is after.
HttpResponse api_change_user(ApiCall& c) {
  auto body = json_body(c.req);
  if (!body) return error_response(c.req, http::status::bad_request, body.error());
  auto change = user_change(*body);
  if (!change) return error_response(c.req, http::status::bad_request, change.error());
  const std::string& name = c.params[0];
  if (auto u = find_user(c.ctx.store, name); !u)
    return error_response(c.req, status_of(u.error()), u.error().message);
  StoreResult<void> done;
  if (change->role) done = set_role(c.ctx.store, name, *change->role, c.actor());
  if (done && change->disabled)
    done = set_disabled(c.ctx.store, name, *change->disabled, c.actor());
  if (done && change->password)
    done = set_password(c.ctx.store, name, *change->password, c.actor());
  if (!done) return error_response(c.req, status_of(done.error()), done.error().message);
  auto after = find_user(c.ctx.store, name);
  if (!after) return error_response(c.req, status_of(after.error()), after.error().message);
  return json_response(c.req, http::status::ok, user_json(*after));
}

// POST /api/users {"name","role","password"} (admin): a new account.
HttpResponse api_create_user(ApiCall& c) {
  auto body = json_body(c.req);
  if (!body) return error_response(c.req, http::status::bad_request, body.error());
  std::string fields[3];
  const std::string_view keys[3] = {"name", "role", "password"};
  for (std::size_t i = 0; i < 3; ++i) {
    auto v = string_field(*body, keys[i], true);
    if (!v) return error_response(c.req, http::status::bad_request, v.error());
    fields[i] = std::move(**v);
  }
  const auto role = parse_role(fields[1]);
  if (!role) {
    return error_response(c.req, http::status::bad_request,
                          "role must be operator, programmer, approver or admin");
  }
  auto user = create_user(c.ctx.store, fields[0], *role, fields[2], c.actor());
  if (!user) return error_response(c.req, status_of(user.error()), user.error().message);
  return json_response(c.req, http::status::created,
                       {{"name", user->name}, {"role", role_name(user->role)}});
}

}  // namespace usina::dnc
