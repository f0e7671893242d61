// usina-serve.toml as the server reads it: the `[[machine]]` tables
// (machine_config.hpp checks their link keys; `machine_class` names the
// class whose programs the machine runs) and the `[server]` table:
//
//   [server]
//   listen = "127.0.0.1:8080"   # --listen overrides it
//   max_upload = 67108864       # bytes of a request body; past it: 413
//   session_hours = 8           # a login's life
//   tls_cert = "server.crt"     # HTTPS and WSS (both or neither; relative to the configuration's
//   folder) tls_key = "server.key"
//
//   [web]
//   root = "web"                # the built page's folder (relative to the configuration's)
//   max_file_bytes = 33554432   # a larger file of it is not served
//
//   [calendar]                  # shifts for utilisation (shift_calendar.hpp); a
//   timezone = "UTC"            # machine's own table [machine.calendar] replaces it
//   shifts = [{days = "mon-fri", start = "06:00", end = "14:00"}]
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <regex>
#include <string>
#include <vector>

#include "core/diagnostic.hpp"
#include "dnc/data_config.hpp"
#include "dnc/link_config.hpp"
#include "dnc/shift_calendar.hpp"
#include "dnc/tool_life_config.hpp"
#include "sim/machine_profile.hpp"

namespace usina::dnc {

struct ServerMachine {
  LinkConfig link;
  std::string machine_class;  // empty: any class
  std::string profile;        // the class's machine profile (a file), checked uploads' travel
  // What the control punches while idle that is machine data, not a program
  // (DPRNT lines): ECMAScript, case-insensitive; group 1 the control's
  // count, or the cycle's seconds. Empty: not looked for.
  std::string part_count_pattern = R"(PART\s*COUNT\s*[:=]?\s*([0-9]+)?)";
  std::string cycle_time_pattern = R"(CYCLE\s*TIME\s*[:=]?\s*([0-9]+(\.[0-9]*)?))";
  // Its shifts (shift_calendar.hpp): its own `calendar` table, else the
  // server's [calendar]; none: utilisation per 24 h day only.
  std::optional<ShiftCalendar> calendar = std::nullopt;
  // Its `tool_life` table (tool_life_config.hpp): the tools with a life.
  ToolLives tool_life = {};
  // Added by an admin through the API (store_machines.hpp), not set in the
  // file: the page may change or retire it.
  bool from_store = false;
};

struct ServerConfig {
  std::vector<ServerMachine> machines;
  std::string listen = "127.0.0.1:8080";
  std::uint64_t max_upload = 64ull << 20;
  double session_hours = 8.0;
  // [server] tls_cert / tls_key (--tls-cert / --tls-key override them): PEM
  // files; both or neither. Empty: plain HTTP.
  std::string tls_cert;
  std::string tls_key;
  MtconnectConfig mtconnect;  // [mtconnect]: the SHDR adapter (data_config.hpp)
  MqttConfig mqtt;            // [mqtt]: events to a broker
  // [calendar]: every machine's shifts, unless it has its own (shift_calendar.hpp).
  std::optional<ShiftCalendar> calendar = std::nullopt;
  // [web] (docs/web.md): the page's folder, as written (serve.cpp makes it
  // relative to the configuration's folder); empty: web_static's default.
  std::string web_root;
  std::uint64_t web_max_file_bytes = 32ull << 20;
  // Each machine class's profile (load_profiles): the store's check of an
  // upload of that class runs on it, travel included.
  std::map<std::string, sim::MachineProfile> profiles;
};

// A machine's data patterns are ECMAScript, case-insensitive.
inline constexpr auto kDataPatternFlags = std::regex::ECMAScript | std::regex::icase;

// The longest data pattern: std::regex compiles and matches by recursion, a
// call or more per character, so a pattern of 100,000 characters (or
// parentheses 10,000 deep) overflows the stack of `usina serve` as it reads
// its configuration.
inline constexpr std::size_t kMaxDataPatternLength = 256;

// The longest line of a punch matched against the data patterns: longer
// lines are no DPRNT output, and matching one of 100,000 characters
// overflows the stack the same way.
inline constexpr std::size_t kMaxDataLineLength = 1024;

// Why `pattern` is not an ECMAScript regular expression (or is longer than
// kMaxDataPatternLength); empty when it is one.
std::string pattern_error(const std::string& pattern);

// The configuration in `toml_text`, or nothing when it has an error
// (reported to `diags`, E_DNC_CONFIG at its line).
std::optional<ServerConfig> read_server_config(std::string_view toml_text, std::uint32_t file_id,
                                               core::DiagnosticSink& diags);

// Reads the `profile` file of each machine (relative to `base_dir`, the
// configuration's folder) into `profiles`, by machine class; false, with
// diagnostics, when one cannot be read or a class has two different files.
bool load_profiles(ServerConfig& config, const std::string& base_dir, core::DiagnosticSink& diags);

}  // namespace usina::dnc
