// --machine PROFILE, as the verbs that time a program read it (stats, simulate).
#pragma once

#include <optional>
#include <string>

#include "sim/machine_profile.hpp"

namespace usina::cli {

// The machine profile at `path`, or the default profile when `path` is
// empty; nullopt after its errors are printed on stderr (an unreadable file,
// a profile with an error).
std::optional<sim::MachineProfile> load_machine_profile(const std::string& path);

}  // namespace usina::cli
