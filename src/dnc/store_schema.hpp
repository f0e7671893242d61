// The store's schema as numbered migrations, the same tables on both back
// ends. A store records the last migration it ran; opening it runs the
// newer ones, each in its own transaction, and refuses a store written by a
// newer usina (its schema is unknown to this one).
#pragma once

#include "dnc/store_db.hpp"

namespace usina::dnc {

// The schema version this usina writes.
int current_schema_version();

// Brings `db` to current_schema_version(); the version it was at before.
StoreResult<int> migrate(Database& db);

}  // namespace usina::dnc
