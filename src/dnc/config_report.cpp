#include "dnc/config_report.hpp"

#include <fmt/format.h>

#include "sim/profile_keys.hpp"

namespace usina::dnc {

void config_error(core::DiagnosticSink& diags, std::uint32_t file_id, const toml::source_region& at,
                  std::string message) {
  core::Diagnostic d;
  d.code = core::Code::DncConfig;
  d.severity = core::Severity::Error;
  d.loc.file = file_id;
  d.loc.line = at.begin.line;
  d.loc.col = at.begin.column;
  d.message = std::move(message);
  diags.report(std::move(d));
}

void config_unknown_key(core::DiagnosticSink& diags, std::uint32_t file_id, const toml::key& key,
                        std::string_view where, std::span<const std::string_view> keys) {
  const std::string_view near = sim::nearest_key(key.str(), keys);
  core::Diagnostic d;
  d.code = core::Code::UnknownDncKey;
  d.severity = core::Severity::Warning;
  d.loc.file = file_id;
  d.loc.line = key.source().begin.line;
  d.loc.col = key.source().begin.column;
  d.message = fmt::format("unknown key `{}` {} is not read; {}", key.str(), where,
                          near.empty() ? std::string("docs/dnc-server.md lists the keys")
                                       : fmt::format("did you mean `{}`?", near));
  diags.report(std::move(d));
}

}  // namespace usina::dnc
