// Diagnostics of usina-serve.toml's readers: a value that cannot be used is
// E_DNC_CONFIG at its line and column; a key usina does not read is the
// warning W_UNKNOWN_DNC_KEY with the nearest known name.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include <toml++/toml.h>

#include "core/diagnostic.hpp"

namespace usina::dnc {

void config_error(core::DiagnosticSink& diags, std::uint32_t file_id, const toml::source_region& at,
                  std::string message);

// `where` says where the key is ("in [server]", "in machine `m1` tool_life.T1").
void config_unknown_key(core::DiagnosticSink& diags, std::uint32_t file_id, const toml::key& key,
                        std::string_view where, std::span<const std::string_view> keys);

}  // namespace usina::dnc
