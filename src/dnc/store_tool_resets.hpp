// Tool-life count resets (schema version 7): a shop resets a tool's count
// when it changes the insert or the cutter, and the tools' answer then counts
// that tool's parts from its last reset (store_utilisation.hpp's tool_life).
// A reset is a row of `tool_resets` and an audit entry (`tool.reset`),
// written in one transaction.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <string_view>

#include "dnc/store.hpp"

namespace usina::dnc {

// The tool numbers a reset takes: the T word's whole number, as the library's
// `tool` filter (a lathe's T0101 is 101).
inline constexpr std::int64_t kMaxToolNumber = 99'999'999;

struct ToolReset {
  std::int64_t tool = 0;
  std::int64_t at_us = 0;
  std::string by;  // the user
  std::string reason;
};

// Resets `tool` of `machine` now (the store's clock), with its audit entry.
// Invalid for a tool number outside 0..kMaxToolNumber or a reason that is not
// free text (store_names.hpp).
StoreResult<ToolReset> reset_tool(Store& store, const Actor& actor, std::string_view machine,
                                  std::int64_t tool, std::string_view reason);

// Each tool's last reset at or before `up_to_us`, by tool number.
StoreResult<std::map<std::int64_t, ToolReset>> last_tool_resets(Store& store,
                                                                std::string_view machine,
                                                                std::int64_t up_to_us);

}  // namespace usina::dnc
