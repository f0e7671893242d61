// What a store operation that fails says: a kind the API layer maps to an
// HTTP status (docs/dnc.md) and a message for a person.
#pragma once

#include <string>
#include <utility>

#include <tl/expected.hpp>

namespace usina::dnc {

enum class StoreErrorKind {
  NotFound,  // no such program, revision, user or session (404)
  Invalid,   // a malformed name, text or argument (400)
  TooLarge,  // past a size limit (413)
  Refused,   // an illegal state transition, a locked login, a failed check (409/403)
  Conflict,  // exists already, or differs from what is stored (409)
  Damaged,   // stored bytes or the audit chain do not match their hashes (500)
  Backend,   // the database failed (500)
};

struct StoreError {
  StoreErrorKind kind = StoreErrorKind::Backend;
  std::string message;
};

template <typename T>
using StoreResult = tl::expected<T, StoreError>;

inline tl::unexpected<StoreError> store_error(StoreErrorKind kind, std::string message) {
  return tl::unexpected(StoreError{kind, std::move(message)});
}

}  // namespace usina::dnc
