// The keys a machine profile may have (docs/stats.md, "Profile keys"), and
// the nearest of them to a misspelt one, so that `per_hours = 60` is a
// warning that says "did you mean `per_hour`?" rather than silently unread.
#pragma once

#include <span>
#include <string_view>

namespace usina::sim {

// The keys of a section ("" for the file's top level, "axes", "axes.x" for
// any axis, "machine", "spindle", "times", "cost", "planner").
std::span<const std::string_view> profile_keys(std::string_view section);

// Edits (insert, delete, replace, or swap two neighbours) from a to b.
std::size_t edit_distance(std::string_view a, std::string_view b);

// The key of `keys` nearest `name`, when it is near enough to be a slip (at
// most 2 edits, and fewer than half the name's length); empty otherwise.
std::string_view nearest_key(std::string_view name, std::span<const std::string_view> keys);

}  // namespace usina::sim
