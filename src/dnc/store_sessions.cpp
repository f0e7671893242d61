// store_users.hpp: logging in, sessions, the first admin.
#include <sodium.h>

#include <array>

#include <fmt/format.h>

#include "dnc/sha256.hpp"
#include "dnc/store_audit.hpp"
#include "dnc/store_names.hpp"
#include "dnc/store_users.hpp"

namespace usina::dnc {
namespace {

constexpr std::int64_t kMicro = 1'000'000;

std::string new_token() {
  std::array<unsigned char, 32> raw{};
  randombytes_buf(raw.data(), raw.size());
  std::array<char, 65> hex{};
  sodium_bin2hex(hex.data(), hex.size(), raw.data(), raw.size());
  return std::string(hex.data());
}

// A hash to verify against when the user does not exist, so that a wrong
// name costs as long as a wrong password.
const std::string& decoy_hash(const Store& store) {
  static const std::string hash = [&store] {
    std::array<char, crypto_pwhash_STRBYTES> out{};
    const std::string decoy = "usina-decoy-password";
    if (crypto_pwhash_str(out.data(), decoy.data(), decoy.size(), store.options().password_ops,
                          store.options().password_memory) != 0)
      return std::string();  // out of memory: verifying against "" fails, as it should
    return std::string(out.data());
  }();
  return hash;
}

struct Account {
  User user;
  std::string password_hash;
};

StoreResult<std::optional<Account>> account(Store& store, std::string_view name) {
  auto rows = store.db().query(
      "SELECT name, role, disabled, created_at, password_hash FROM users WHERE name = $1", {name});
  if (!rows) return tl::unexpected(rows.error());
  if (rows->empty()) return std::optional<Account>();
  const SqlRow& r = rows->front();
  return std::optional<Account>(Account{
      {r.text(0), parse_role(r.text(1)).value_or(Role::Operator), r.integer(2) != 0, r.integer(3)},
      r.text(4)});
}

StoreResult<void> record_attempt(Store& store, std::string_view name, std::string_view origin,
                                 bool ok) {
  auto r = store.db().query(
      "INSERT INTO login_attempts (user_name, origin, at, ok) VALUES ($1, $2, $3, $4)",
      {name, origin, store.now_us(), std::int64_t{ok ? 1 : 0}});
  if (!r) return tl::unexpected(r.error());
  auto a = append_audit(store, {std::string(name), std::string(origin)},
                        {ok ? "login" : "login.failed", std::string(name), "", "{}"});
  if (!a) return tl::unexpected(a.error());
  return {};
}

StoreResult<Session> open_session(Store& store, const User& user) {
  Session s{new_token(), user, store.now_us() + store.options().session_seconds * kMicro};
  auto r = store.db().query(
      "INSERT INTO sessions (token_hash, user_name, created_at, expires_at) "
      "VALUES ($1, $2, $3, $4)",
      {std::string_view(sha256_hex(s.token)), std::string_view(user.name), store.now_us(),
       s.expires_at_us});
  if (!r) return tl::unexpected(r.error());
  return s;
}

// Limits, then the password (the expensive part, outside the transaction).
StoreResult<std::optional<User>> check_login(Store& store, std::string_view name,
                                             std::string_view password, std::string_view origin) {
  auto wait = login_wait_seconds(store, name, origin);
  if (!wait) return tl::unexpected(wait.error());
  if (*wait > 0) {
    return store_error(StoreErrorKind::Refused,
                       fmt::format("too many failed logins; try again in {} s", *wait));
  }
  auto acc = account(store, name);
  if (!acc) return tl::unexpected(acc.error());
  const std::string& stored = *acc ? (*acc)->password_hash : decoy_hash(store);
  const bool match =
      crypto_pwhash_str_verify(stored.c_str(), password.data(), password.size()) == 0;
  if (!*acc || !match || (*acc)->user.disabled) return std::optional<User>();
  return std::optional<User>((*acc)->user);
}

}  // namespace

StoreResult<Session> log_in(Store& store, std::string_view name, std::string_view password,
                            std::string_view origin) {
  if (auto r = check_text("origin", origin, kMaxOriginBytes); !r) return tl::unexpected(r.error());
  // A malformed name is a failed login like any other (recorded under a safe name).
  const bool named = check_name("user name", name).has_value();
  const std::string recorded = named ? std::string(name) : std::string("?");
  auto user = check_login(store, recorded, password, origin);
  if (!user) return tl::unexpected(user.error());
  Transaction tx(store.db());
  if (auto b = tx.begin_write(); !b) return tl::unexpected(b.error());
  if (auto r = record_attempt(store, recorded, origin, user->has_value()); !r)
    return tl::unexpected(r.error());
  if (!*user) {
    if (auto c = tx.commit(); !c) return tl::unexpected(c.error());
    return store_error(StoreErrorKind::Refused, "wrong user name or password");
  }
  auto s = open_session(store, **user);
  if (!s) return s;
  if (auto c = tx.commit(); !c) return tl::unexpected(c.error());
  return s;
}

StoreResult<Session> verify_session(Store& store, std::string_view token) {
  if (!is_sha256_hex(token)) return store_error(StoreErrorKind::NotFound, "no such session");
  auto rows = store.db().query(
      "SELECT u.name, u.role, u.disabled, u.created_at, s.expires_at FROM sessions s "
      "JOIN users u ON u.name = s.user_name WHERE s.token_hash = $1",
      {std::string_view(sha256_hex(token))});
  if (!rows) return tl::unexpected(rows.error());
  if (rows->empty()) return store_error(StoreErrorKind::NotFound, "no such session");
  const SqlRow& r = rows->front();
  Session s{
      std::string(token),
      {r.text(0), parse_role(r.text(1)).value_or(Role::Operator), r.integer(2) != 0, r.integer(3)},
      r.integer(4)};
  if (s.expires_at_us <= store.now_us())
    return store_error(StoreErrorKind::NotFound, "the session has expired; log in again");
  if (s.user.disabled)
    return store_error(StoreErrorKind::NotFound, fmt::format("user {} is disabled", s.user.name));
  return s;
}

StoreResult<void> log_out(Store& store, std::string_view token) {
  auto r = store.db().query("DELETE FROM sessions WHERE token_hash = $1",
                            {std::string_view(sha256_hex(token))});
  if (!r) return tl::unexpected(r.error());
  return {};
}

StoreResult<std::int64_t> purge_expired(Store& store) {
  const std::int64_t now = store.now_us();
  auto s =
      store.db().query("DELETE FROM sessions WHERE expires_at <= $1 RETURNING token_hash", {now});
  if (!s) return tl::unexpected(s.error());
  auto a = store.db().query("DELETE FROM login_attempts WHERE at <= $1 RETURNING id",
                            {now - store.options().failure_window_seconds * kMicro});
  if (!a) return tl::unexpected(a.error());
  return static_cast<std::int64_t>(s->size() + a->size());
}

StoreResult<User> create_first_admin(Store& store, std::string_view name,
                                     std::string_view password) {
  auto rows = store.db().query("SELECT COUNT(*) FROM users");
  if (!rows) return tl::unexpected(rows.error());
  if (rows->front().integer(0) > 0) {
    return store_error(StoreErrorKind::Conflict,
                       "the store has users already; the first admin is made only once");
  }
  return create_user(store, name, Role::Admin, password, {std::string(name), "init"});
}

}  // namespace usina::dnc
