#include "dnc/machine_settings.hpp"

#include <algorithm>
#include <array>
#include <sstream>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "dnc/machine_config.hpp"
#include "sim/profile_keys.hpp"

namespace usina::dnc {
namespace {

constexpr std::array<std::string_view, 3> kFileOnly{"profile", "calendar", "tool_life"};

// The value of `key` as TOML, or why it cannot be one.
tl::expected<void, std::string> put(toml::table& t, const std::string& key,
                                    const nlohmann::json& v) {
  if (v.is_string()) {
    t.insert(key, v.get<std::string>());
  } else if (v.is_boolean()) {
    t.insert(key, v.get<bool>());
  } else if (v.is_number_integer()) {
    t.insert(key, v.get<std::int64_t>());
  } else if (v.is_number_unsigned()) {
    t.insert(key, static_cast<double>(v.get<std::uint64_t>()));  // past int64: the range says no
  } else if (v.is_number_float()) {
    t.insert(key, v.get<double>());
  } else {
    return tl::unexpected(fmt::format("{} must be a string, a number or true/false", key));
  }
  return {};
}

tl::expected<toml::table, std::string> as_table(const nlohmann::json& settings) {
  if (!settings.is_object())
    return tl::unexpected(std::string("the machine's settings must be a JSON object"));
  const auto keys = machine_keys();
  toml::table t;
  for (const auto& [key, value] : settings.items()) {
    if (std::find(kFileOnly.begin(), kFileOnly.end(), key) != kFileOnly.end())
      return tl::unexpected(
          fmt::format("{} names a file or table of usina-serve.toml: set it there", key));
    if (std::find(keys.begin(), keys.end(), key) == keys.end()) {
      const std::string_view near = sim::nearest_key(key, keys);
      return tl::unexpected(fmt::format("unknown key `{}`{}", key,
                                        near.empty()
                                            ? std::string(" (docs/dnc-links.md lists them)")
                                            : fmt::format("; did you mean `{}`?", near)));
    }
    if (auto ok = put(t, key, value); !ok) return tl::unexpected(ok.error());
  }
  return t;
}

}  // namespace

tl::expected<ServerMachine, std::string> machine_from_settings(const nlohmann::json& settings) {
  auto table = as_table(settings);
  if (!table) return tl::unexpected(table.error());
  toml::table root;
  root.insert("machine", toml::array{std::move(*table)});
  std::ostringstream text;
  text << root;
  core::DiagnosticList diags;
  auto config = read_server_config(text.str(), 0, diags);
  if (!config || config->machines.size() != 1) {
    std::string why;
    for (const core::Diagnostic& d : diags.all()) {
      if (d.severity == core::Severity::Error)
        why += fmt::format("{}{}", why.empty() ? "" : "\n", d.message);
    }
    return tl::unexpected(why.empty() ? std::string("the settings describe no machine") : why);
  }
  return std::move(config->machines.front());
}

nlohmann::json machine_settings(const ServerMachine& m) {
  const LinkConfig& l = m.link;
  return {{"name", l.name},
          {"dialect", l.dialect},
          {"port", l.port},
          {"machine_class", m.machine_class},
          {"baud", l.baud},
          {"data_bits", l.data_bits},
          {"parity", parity_name(l.parity)},
          {"stop_bits", l.stop_bits},
          {"flow", flow_name(l.flow)},
          {"code", code_name(l.code)},
          {"eob", eob_name(l.eob)},
          {"mode", mode_name(l.mode)},
          {"skid", l.skid},
          {"xon", l.xon},
          {"xoff", l.xoff},
          {"leader", l.leader},
          {"trailer", l.trailer},
          {"wait_for_xon", l.wait_for_xon},
          {"xon_timeout", l.xon_timeout},
          {"receive_idle", l.receive_idle},
          {"request_program", l.request_program},
          {"request_lines", l.request_lines},
          {"part_count_pattern", m.part_count_pattern},
          {"cycle_time_pattern", m.cycle_time_pattern}};
}

}  // namespace usina::dnc
