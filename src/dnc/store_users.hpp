// Accounts, passwords, sessions and login limits, store side (the API layer
// speaks HTTP around them). A password is kept only as an argon2id hash
// (libsodium's crypto_pwhash_str, its cost in StoreOptions); a session token
// is 32 random bytes given once to the client, and only its SHA-256 is kept,
// so a copy of the database opens no session. Every failed login is
// recorded; too many failures within the window, for a user or from an
// origin, refuse further logins (even with the right password) until the
// window has passed since the last failure.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "dnc/store.hpp"
#include "dnc/store_roles.hpp"

namespace usina::dnc {

struct User {
  std::string name;
  Role role = Role::Operator;
  bool disabled = false;
  std::int64_t created_at_us = 0;
};

struct Session {
  std::string token;  // give it to the client; the store keeps only its hash
  User user;
  std::int64_t expires_at_us = 0;
};

StoreResult<User> create_user(Store& store, std::string_view name, Role role,
                              std::string_view password, const Actor& actor);
StoreResult<User> find_user(Store& store, std::string_view name);
StoreResult<void> set_password(Store& store, std::string_view name, std::string_view password,
                               const Actor& actor);
StoreResult<void> set_disabled(Store& store, std::string_view name, bool disabled,
                               const Actor& actor);
// A new role; audited (user.role) when it changes.
StoreResult<void> set_role(Store& store, std::string_view name, Role role, const Actor& actor);
// Every account, by name (the admin's users page).
StoreResult<std::vector<User>> list_users(Store& store);
// set_role and set_disabled refuse (Refused) to leave the store without an
// enabled admin: nobody could make users or import programs again.

// Checks the login limits, then the password; records the attempt (and an
// audit entry); a new session on success. A wrong user and a wrong password
// get the same answer.
StoreResult<Session> log_in(Store& store, std::string_view name, std::string_view password,
                            std::string_view origin);
// The session's user, when the token is known, unexpired and its user enabled.
StoreResult<Session> verify_session(Store& store, std::string_view token);
StoreResult<void> log_out(Store& store, std::string_view token);
// Removes expired sessions and login attempts older than the window; how many.
StoreResult<std::int64_t> purge_expired(Store& store);

// Seconds until a login for `name` from `origin` is allowed again; 0 now.
StoreResult<std::int64_t> login_wait_seconds(Store& store, std::string_view name,
                                             std::string_view origin);

// `usina serve --init`: the first admin of a store that has no users yet.
StoreResult<User> create_first_admin(Store& store, std::string_view name,
                                     std::string_view password);

constexpr std::size_t kMinPasswordBytes = 8;
constexpr std::size_t kMaxPasswordBytes = 1024;

// Invalid unless the password has kMinPasswordBytes to kMaxPasswordBytes
// (what every setter checks; the API asks before it writes anything).
StoreResult<void> check_password(std::string_view password);

}  // namespace usina::dnc
