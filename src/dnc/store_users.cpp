#include "dnc/store_users.hpp"

#include <sodium.h>

#include <array>

#include <fmt/format.h>

#include "dnc/store_audit.hpp"
#include "dnc/store_names.hpp"

namespace usina::dnc {
namespace {

constexpr std::int64_t kMicro = 1'000'000;

StoreResult<std::string> hash_password(const Store& store, std::string_view password) {
  if (auto ok = check_password(password); !ok) return tl::unexpected(ok.error());
  std::array<char, crypto_pwhash_STRBYTES> out{};
  if (crypto_pwhash_str(out.data(), password.data(), password.size(), store.options().password_ops,
                        store.options().password_memory) != 0) {
    return store_error(StoreErrorKind::Backend, "argon2id ran out of memory hashing a password");
  }
  return std::string(out.data());
}

User user_of(const SqlRow& r) {
  return {r.text(0), parse_role(r.text(1)).value_or(Role::Operator), r.integer(2) != 0,
          r.integer(3)};
}

StoreResult<void> audit_only(Store& store, const Actor& actor, const AuditRecord& record) {
  auto a = append_audit(store, actor, record);
  if (!a) return tl::unexpected(a.error());
  return {};
}

// Runs `write` and its audit entry in one write transaction.
template <typename F>
StoreResult<void> in_write(Store& store, F&& write) {
  Transaction tx(store.db());
  if (auto b = tx.begin_write(); !b) return b;
  if (auto w = write(); !w) return w;
  return tx.commit();
}

// Refused when `name` is the only enabled admin (inside the write).
StoreResult<void> refuse_last_admin(Store& store, std::string_view name,
                                    const std::string& change) {
  auto rows = store.db().query(
      "SELECT COUNT(*) FROM users WHERE role = 'admin' AND disabled = 0 AND name <> $1", {name});
  if (!rows) return tl::unexpected(rows.error());
  if (rows->front().integer(0) > 0) return {};
  return store_error(StoreErrorKind::Refused,
                     fmt::format("{} is the only enabled admin and cannot be {}: make another "
                                 "admin first",
                                 name, change));
}

}  // namespace

StoreResult<void> check_password(std::string_view password) {
  if (password.size() < kMinPasswordBytes || password.size() > kMaxPasswordBytes) {
    return store_error(StoreErrorKind::Invalid,
                       fmt::format("a password has {} to {} bytes; this one has {}",
                                   kMinPasswordBytes, kMaxPasswordBytes, password.size()));
  }
  return {};
}

StoreResult<User> create_user(Store& store, std::string_view name, Role role,
                              std::string_view password, const Actor& actor) {
  if (auto r = check_name("user name", name); !r) return tl::unexpected(r.error());
  auto hash = hash_password(store, password);
  if (!hash) return tl::unexpected(hash.error());
  const std::int64_t now = store.now_us();
  auto done = in_write(store, [&]() -> StoreResult<void> {
    if (find_user(store, name)) {
      return store_error(StoreErrorKind::Conflict, fmt::format("user {} exists already", name));
    }
    auto r = store.db().query(
        "INSERT INTO users (name, role, password_hash, created_at) VALUES ($1, $2, $3, $4)",
        {name, role_name(role), std::string_view(*hash), now});
    if (!r) return tl::unexpected(r.error());
    return audit_only(
        store, actor,
        {"user.create", std::string(name), "", fmt::format(R"({{"role":"{}"}})", role_name(role))});
  });
  if (!done) return tl::unexpected(done.error());
  return User{std::string(name), role, false, now};
}

StoreResult<User> find_user(Store& store, std::string_view name) {
  auto rows = store.db().query("SELECT name, role, disabled, created_at FROM users WHERE name = $1",
                               {name});
  if (!rows) return tl::unexpected(rows.error());
  if (rows->empty()) return store_error(StoreErrorKind::NotFound, fmt::format("no user {}", name));
  return user_of(rows->front());
}

StoreResult<void> set_password(Store& store, std::string_view name, std::string_view password,
                               const Actor& actor) {
  auto hash = hash_password(store, password);
  if (!hash) return tl::unexpected(hash.error());
  return in_write(store, [&]() -> StoreResult<void> {
    if (auto u = find_user(store, name); !u) return tl::unexpected(u.error());
    auto r = store.db().query("UPDATE users SET password_hash = $1 WHERE name = $2",
                              {std::string_view(*hash), name});
    if (!r) return tl::unexpected(r.error());
    // A new password ends the sessions opened with the old one.
    r = store.db().query("DELETE FROM sessions WHERE user_name = $1", {name});
    if (!r) return tl::unexpected(r.error());
    return audit_only(store, actor, {"user.password", std::string(name), "", "{}"});
  });
}

StoreResult<void> set_disabled(Store& store, std::string_view name, bool disabled,
                               const Actor& actor) {
  return in_write(store, [&]() -> StoreResult<void> {
    auto u = find_user(store, name);
    if (!u) return tl::unexpected(u.error());
    if (u->disabled == disabled) return {};
    if (disabled && u->role == Role::Admin) {
      if (auto last = refuse_last_admin(store, name, "disabled"); !last) return last;
    }
    auto r = store.db().query("UPDATE users SET disabled = $1 WHERE name = $2",
                              {std::int64_t{disabled ? 1 : 0}, name});
    if (!r) return tl::unexpected(r.error());
    // A disabled account's sessions end now, not when they expire.
    if (disabled) r = store.db().query("DELETE FROM sessions WHERE user_name = $1", {name});
    if (!r) return tl::unexpected(r.error());
    return audit_only(store, actor,
                      {disabled ? "user.disable" : "user.enable", std::string(name), "", "{}"});
  });
}

StoreResult<void> set_role(Store& store, std::string_view name, Role role, const Actor& actor) {
  return in_write(store, [&]() -> StoreResult<void> {
    auto u = find_user(store, name);
    if (!u) return tl::unexpected(u.error());
    if (u->role == role) return {};
    if (u->role == Role::Admin && !u->disabled) {
      if (auto last = refuse_last_admin(store, name, "made " + std::string(role_name(role))); !last)
        return last;
    }
    auto r =
        store.db().query("UPDATE users SET role = $1 WHERE name = $2", {role_name(role), name});
    if (!r) return tl::unexpected(r.error());
    return audit_only(
        store, actor,
        {"user.role", std::string(name), "",
         fmt::format(R"({{"from":"{}","to":"{}"}})", role_name(u->role), role_name(role))});
  });
}

StoreResult<std::vector<User>> list_users(Store& store) {
  auto rows =
      store.db().query("SELECT name, role, disabled, created_at FROM users ORDER BY name", {});
  if (!rows) return tl::unexpected(rows.error());
  std::vector<User> users;
  users.reserve(rows->size());
  for (const SqlRow& r : *rows)
    users.push_back(user_of(r));
  return users;
}

StoreResult<std::int64_t> login_wait_seconds(Store& store, std::string_view name,
                                             std::string_view origin) {
  const StoreOptions& o = store.options();
  const std::int64_t since = store.now_us() - o.failure_window_seconds * kMicro;
  std::int64_t wait = 0;
  const auto count = [&](std::string_view column, std::string_view value,
                         int limit) -> StoreResult<void> {
    auto rows = store.db().query(
        fmt::format("SELECT COUNT(*), MAX(at) FROM login_attempts WHERE {} = $1 AND ok = 0 "
                    "AND at > $2",
                    column),
        {value, since});
    if (!rows) return tl::unexpected(rows.error());
    const SqlRow& r = rows->front();
    if (r.integer(0) < limit) return {};
    const std::int64_t until = r.integer(1) + o.failure_window_seconds * kMicro;
    wait = std::max(wait, (until - store.now_us() + kMicro - 1) / kMicro);
    return {};
  };
  if (auto c = count("user_name", name, o.max_failures_per_user); !c)
    return tl::unexpected(c.error());
  if (auto c = count("origin", origin, o.max_failures_per_origin); !c)
    return tl::unexpected(c.error());
  return wait;
}

}  // namespace usina::dnc
