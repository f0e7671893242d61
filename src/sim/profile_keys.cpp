#include "sim/profile_keys.hpp"

#include <algorithm>
#include <array>
#include <vector>

namespace usina::sim {
namespace {

constexpr std::array<std::string_view, 6> kTop = {"machine", "axes", "spindle",
                                                  "times",   "cost", "planner"};
constexpr std::array<std::string_view, 6> kAxes = {"x", "y", "z", "a", "b", "c"};
constexpr std::array<std::string_view, 6> kAxis = {"min",   "max",  "rapid",
                                                   "accel", "jerk", "max_feed"};
constexpr std::array<std::string_view, 2> kMachine = {"name", "units"};
constexpr std::array<std::string_view, 2> kSpindle = {"max_rpm", "accel_time"};
constexpr std::array<std::string_view, 2> kTimes = {"tool_change", "block"};
constexpr std::array<std::string_view, 1> kCost = {"per_hour"};
constexpr std::array<std::string_view, 10> kPlanner = {
    "junction_deviation", "model",      "servo_period",   "max_velocity",       "kink_ratio",
    "arc_blend",          "gap_cycles", "max_feed_scale", "optimization_depth", "arc_tolerance"};

}  // namespace

std::span<const std::string_view> profile_keys(std::string_view section) {
  if (section.empty()) return kTop;
  if (section == "axes") return kAxes;
  if (section.starts_with("axes.")) return kAxis;
  if (section == "machine") return kMachine;
  if (section == "spindle") return kSpindle;
  if (section == "times") return kTimes;
  if (section == "cost") return kCost;
  if (section == "planner") return kPlanner;
  return {};
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  // Optimal string alignment: Levenshtein plus the swap of two neighbours
  // (per_huor → per_hour is one slip, not two).
  const std::size_t n = a.size();
  const std::size_t m = b.size();
  std::vector<std::vector<std::size_t>> d(n + 1, std::vector<std::size_t>(m + 1));
  for (std::size_t i = 0; i <= n; ++i)
    d[i][0] = i;
  for (std::size_t j = 0; j <= m; ++j)
    d[0][j] = j;
  for (std::size_t i = 1; i <= n; ++i) {
    for (std::size_t j = 1; j <= m; ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
      }
    }
  }
  return d[n][m];
}

std::string_view nearest_key(std::string_view name, std::span<const std::string_view> keys) {
  constexpr std::size_t kMaxLength = 64;  // a longer name is no slip of a key
  if (name.size() > kMaxLength) return {};
  std::string_view best;
  std::size_t best_distance = 3;
  for (const std::string_view k : keys) {
    const std::size_t d = edit_distance(name, k);
    if (d < best_distance && 2 * d < std::max(name.size(), k.size())) {
      best = k;
      best_distance = d;
    }
  }
  return best;
}

}  // namespace usina::sim
