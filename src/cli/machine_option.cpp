#include "cli/machine_option.hpp"

#include <cstdint>
#include <cstdio>
#include <string_view>

#include <fmt/format.h>

#include "core/diagnostic.hpp"
#include "core/source.hpp"
#include "sim/stats.hpp"

namespace usina::cli {
namespace {

// toml++ gives line and column; the renderer also wants the line's offset.
void locate_line(core::Diagnostic& d, std::string_view text) {
  std::uint64_t offset = 0;
  for (std::uint32_t line = 1; line < d.loc.line && offset < text.size(); ++line) {
    const std::size_t nl = text.find('\n', offset);
    if (nl == std::string_view::npos) break;
    offset = nl + 1;
  }
  d.loc.line_offset = offset;
}

}  // namespace

// Reads --machine, or the default profile; nullopt (after saying why) when unusable.
std::optional<sim::MachineProfile> load_machine_profile(const std::string& path) {
  if (path.empty()) return sim::default_machine_profile();
  std::string err;
  core::SourceManager sources;
  auto file = core::SourceFile::open(path, err);
  if (!file) {
    fmt::print(stderr, "usina: error: cannot read {}: {}\n", path, err);
    return std::nullopt;
  }
  const std::string_view text = file->text();
  const std::uint32_t id = sources.add(std::move(file));
  core::DiagnosticList diags;
  auto profile = sim::read_machine_profile(text, id, diags);
  for (core::Diagnostic d : diags.all()) {
    locate_line(d, text);
    const std::string out = core::render(d, sources);
    std::fwrite(out.data(), 1, out.size(), stderr);
  }
  if (!profile) fmt::print(stderr, "usina: error: the machine profile {} cannot be used\n", path);
  return profile;
}

}  // namespace usina::cli
