// The `[[machine]]` tables of usina-serve.toml (spec/dnc-api.md) read into
// link configurations, every value checked: a value no link can use is
// E_DNC_CONFIG at its line, a key usina does not read is W_UNKNOWN_DNC_KEY
// with the nearest valid name (as machine profiles do, sim/profile_keys).
// Other tables of the file are not this reader's business.
#pragma once

#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "core/diagnostic.hpp"
#include "dnc/link_config.hpp"

namespace usina::dnc {

// The keys a `[[machine]]` table may have.
std::span<const std::string_view> machine_keys();

// Every machine of the file, or nothing when one of them has an error.
std::optional<std::vector<LinkConfig>> read_machine_links(std::string_view toml_text,
                                                          std::uint32_t file_id,
                                                          core::DiagnosticSink& diags);

}  // namespace usina::dnc
