// The machines an admin adds through the API (schema version 11), kept
// beside those of usina-serve.toml: each one's settings as JSON with the
// keys of a [[machine]] table (machine_settings.hpp reads them), and its
// retirement. A machine is never deleted: retired, its row keeps its name
// (the jobs, utilisation and quality records under it stay its own), so no
// later machine takes that name. Each change is an audit entry
// (`machine.add`, `machine.change`, `machine.retire`) in its transaction.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "dnc/store.hpp"

namespace usina::dnc {

struct StoredMachine {
  std::string name;
  std::string settings;  // JSON: the [[machine]] keys the admin gave
  std::int64_t created_at_us = 0;
  std::string created_by;
  std::int64_t changed_at_us = 0;
  std::int64_t retired_at_us = 0;  // 0 while in service
  std::string retired_by;
  std::string retire_reason;
};

// Conflict when a machine of that name was stored already (retired too).
StoreResult<StoredMachine> add_machine(Store& store, const Actor& actor, std::string_view name,
                                       std::string_view settings, std::string_view reason);
// New settings for a machine in service; `changed` (JSON) names what
// changed, for the audit entry. NotFound for no such machine, Refused for a
// retired one.
StoreResult<StoredMachine> change_machine(Store& store, const Actor& actor, std::string_view name,
                                          std::string_view settings, std::string_view changed,
                                          std::string_view reason);
StoreResult<StoredMachine> retire_machine(Store& store, const Actor& actor, std::string_view name,
                                          std::string_view reason);

StoreResult<std::vector<StoredMachine>> stored_machines(Store& store);

}  // namespace usina::dnc
