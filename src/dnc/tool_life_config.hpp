// A machine's tool lives (`[machine.tool_life]` of usina-serve.toml,
// docs/dnc.md "Tool life"): after how many parts, or minutes of cutting, a
// tool is worn, counted from its last reset. The page shows each tool's
// share of its life and says when it is worn; the count itself is the
// store's (store_utilisation.hpp).
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string_view>

#include <toml++/toml.h>

#include "core/diagnostic.hpp"

namespace usina::dnc {

inline constexpr std::int64_t kMaxLifeParts = 1'000'000'000;
inline constexpr double kMaxLifeMinutes = 1'000'000.0;  // about two years of cutting
inline constexpr std::size_t kMaxToolLives = 1000;

struct ToolLifeLimit {
  std::optional<std::int64_t> parts;      // 1 to kMaxLifeParts
  std::optional<double> cutting_minutes;  // above 0, at most kMaxLifeMinutes
};

using ToolLives = std::map<std::int64_t, ToolLifeLimit>;  // by tool number

// The table `{T1 = {parts = 500}, T2 = {cutting_minutes = 90, parts = 200}}`
// of the machine `machine`: nothing (and E_DNC_CONFIG at the value) when a
// tool or a value cannot be used; an unknown key is W_UNKNOWN_DNC_KEY.
std::optional<ToolLives> read_tool_lives(const toml::table& table, std::string_view machine,
                                         std::uint32_t file_id, core::DiagnosticSink& diags);

// The share of its life a tool has used (1 is worn): the larger of parts
// over its parts and minutes over its minutes; nothing without a life.
std::optional<double> life_used(const ToolLifeLimit& life, std::int64_t parts,
                                double cutting_seconds);

}  // namespace usina::dnc
