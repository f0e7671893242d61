#include "dnc/tool_life_config.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>

#include <fmt/format.h>

#include "dnc/config_report.hpp"
#include "dnc/store_tool_resets.hpp"

namespace usina::dnc {
namespace {

constexpr std::array<std::string_view, 2> kLifeKeys{"parts", "cutting_minutes"};

// "T5" (or "t5"): 5; nothing for anything else.
std::optional<std::int64_t> tool_key(std::string_view key) {
  if (key.size() < 2 || (key.front() != 'T' && key.front() != 't')) return std::nullopt;
  key.remove_prefix(1);
  std::int64_t n = -1;
  const auto [end, ec] = std::from_chars(key.data(), key.data() + key.size(), n);
  if (ec != std::errc() || end != key.data() + key.size() || n < 0 || n > kMaxToolNumber)
    return std::nullopt;
  return n;
}

class LifeReader {
 public:
  LifeReader(std::string_view machine, std::uint32_t file, core::DiagnosticSink& diags)
      : machine_(machine), file_(file), diags_(diags) {}

  std::optional<ToolLifeLimit> tool(const toml::key& key, const toml::node& node) {
    const toml::table* t = node.as_table();
    if (t == nullptr) {
      fail(node.source(), fmt::format("machine `{}`: tool_life.{} must be a table such as "
                                      "{{parts = 500, cutting_minutes = 90}}",
                                      machine_, key.str()));
      return std::nullopt;
    }
    for (auto&& [k, v] : *t) {
      (void)v;
      if (std::find(kLifeKeys.begin(), kLifeKeys.end(), k.str()) == kLifeKeys.end())
        config_unknown_key(diags_, file_, k,
                           fmt::format("in machine `{}` tool_life.{}", machine_, key.str()),
                           kLifeKeys);
    }
    ToolLifeLimit life;
    if (const toml::node* n = t->get("parts")) {
      const auto v = n->value_exact<std::int64_t>();
      if (!v || *v < 1 || *v > kMaxLifeParts) {
        fail(n->source(), fmt::format("machine `{}`: tool_life.{}.parts must be a whole number "
                                      "from 1 to {}",
                                      machine_, key.str(), kMaxLifeParts));
        return std::nullopt;
      }
      life.parts = *v;
    }
    if (const toml::node* n = t->get("cutting_minutes")) {
      const auto v = n->value<double>();
      if (!v || !std::isfinite(*v) || *v <= 0 || *v > kMaxLifeMinutes) {
        fail(n->source(), fmt::format("machine `{}`: tool_life.{}.cutting_minutes must be a "
                                      "number above 0 and at most {}",
                                      machine_, key.str(), kMaxLifeMinutes));
        return std::nullopt;
      }
      life.cutting_minutes = *v;
    }
    if (!life.parts && !life.cutting_minutes) {
      fail(t->source(), fmt::format("machine `{}`: tool_life.{} gives neither parts nor "
                                    "cutting_minutes: a life needs one of them",
                                    machine_, key.str()));
      return std::nullopt;
    }
    return life;
  }

  void fail(const toml::source_region& at, std::string message) {
    config_error(diags_, file_, at, std::move(message));
  }

 private:
  std::string_view machine_;
  std::uint32_t file_;
  core::DiagnosticSink& diags_;
};

}  // namespace

std::optional<ToolLives> read_tool_lives(const toml::table& table, std::string_view machine,
                                         std::uint32_t file_id, core::DiagnosticSink& diags) {
  LifeReader r(machine, file_id, diags);
  if (table.size() > kMaxToolLives) {
    r.fail(table.source(), fmt::format("machine `{}`: tool_life gives {} tools; at most {}",
                                       machine, table.size(), kMaxToolLives));
    return std::nullopt;
  }
  ToolLives lives;
  bool ok = true;
  for (auto&& [key, node] : table) {
    const auto tool = tool_key(key.str());
    if (!tool) {
      r.fail(key.source(), fmt::format("machine `{}`: tool_life.{} is no tool: write T and its "
                                       "number, T0 to T{}",
                                       machine, key.str(), kMaxToolNumber));
      ok = false;
      continue;
    }
    auto life = r.tool(key, node);
    if (!life) {
      ok = false;
      continue;
    }
    if (!lives.emplace(*tool, *life).second) {
      r.fail(key.source(), fmt::format("machine `{}`: tool_life gives T{} twice", machine, *tool));
      ok = false;
    }
  }
  if (!ok) return std::nullopt;
  return lives;
}

std::optional<double> life_used(const ToolLifeLimit& life, std::int64_t parts,
                                double cutting_seconds) {
  std::optional<double> used;
  if (life.parts) used = static_cast<double>(parts) / static_cast<double>(*life.parts);
  if (life.cutting_minutes) {
    const double by_time = cutting_seconds / 60.0 / *life.cutting_minutes;
    used = used ? std::max(*used, by_time) : by_time;
  }
  return used;
}

}  // namespace usina::dnc
