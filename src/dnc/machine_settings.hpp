// A machine's settings as the API takes them (docs/dnc-server.md, "Machines
// added from the page"): a JSON object with the keys of a [[machine]] table,
// read by the same reader as usina-serve.toml (the object is written as that
// table and read back), so a machine added from the page is checked exactly
// as one in the file, with the same messages. `profile` and `calendar` name
// files and tables of the configuration's folder: those stay in the file.
#pragma once

#include <string>

#include <nlohmann/json.hpp>
#include <tl/expected.hpp>

#include "dnc/server_config.hpp"

namespace usina::dnc {

// The machine the settings describe, or what is wrong with them (one line
// per error; an unknown key names the nearest one).
tl::expected<ServerMachine, std::string> machine_from_settings(const nlohmann::json& settings);

// The settings of a machine, every key with its value (the defaults too):
// what the page's form is filled with.
nlohmann::json machine_settings(const ServerMachine& m);

}  // namespace usina::dnc
