// A revision's bytes, stored once under their SHA-256 and checked against
// it on every read: bytes changed on disk or in the database are reported
// (StoreErrorKind::Damaged), never handed to a machine.
#pragma once

#include <string>
#include <string_view>

#include "dnc/store.hpp"

namespace usina::dnc {

// Inside the caller's write transaction; a blob already stored is kept as it is.
StoreResult<void> put_blob(Store& store, std::string_view hash, std::string_view bytes);

// The bytes stored under `hash`, verified.
StoreResult<std::string> read_blob(Store& store, std::string_view hash);

}  // namespace usina::dnc
