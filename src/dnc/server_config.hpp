// usina-serve.toml as the server reads it: the `[[machine]]` tables
// (machine_config.hpp checks their link keys; `machine_class` names the
// class whose programs the machine runs) and the `[server]` table:
//
//   [server]
//   listen = "127.0.0.1:8080"   # --listen overrides it
//   max_upload = 67108864       # bytes of a request body; past it: 413
//   session_hours = 8           # a login's life
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/diagnostic.hpp"
#include "dnc/link_config.hpp"

namespace usina::dnc {

struct ServerMachine {
  LinkConfig link;
  std::string machine_class;  // empty: any class
};

struct ServerConfig {
  std::vector<ServerMachine> machines;
  std::string listen = "127.0.0.1:8080";
  std::uint64_t max_upload = 64ull << 20;
  double session_hours = 8.0;
};

// The configuration in `toml_text`, or nothing when it has an error
// (reported to `diags`, E_DNC_CONFIG at its line).
std::optional<ServerConfig> read_server_config(std::string_view toml_text, std::uint32_t file_id,
                                               core::DiagnosticSink& diags);

}  // namespace usina::dnc
