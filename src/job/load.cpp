#include "job/load.hpp"

#include <filesystem>

#include <fmt/format.h>

#include "job/toml_reader.hpp"
#include "job/tool_table_library.hpp"

namespace usina::job {
namespace {

// The file's text, kept in `sources`; nullopt (io_error set) when unreadable.
std::optional<std::pair<std::string_view, std::uint32_t>> open(const std::string& path,
                                                               core::SourceManager& sources,
                                                               std::string& io_error) {
  std::string err;
  auto file = core::SourceFile::open(path, err);
  if (!file) {
    io_error = fmt::format("cannot read {}: {}", path, err);
    return std::nullopt;
  }
  const std::string_view text = file->text();
  return std::pair{text, sources.add(std::move(file))};
}

// The machine profile's reader gives lines without their offsets: they are
// found here, so its diagnostics show their line too.
class LocatedLines final : public core::DiagnosticSink {
 public:
  LocatedLines(core::DiagnosticSink& next, std::string_view text) : next_(next), lines_(text) {}

  void report(core::Diagnostic d) override {
    if (d.loc.line > 0) d.loc.line_offset = lines_.offset(d.loc.line);
    next_.report(std::move(d));
  }

 private:
  core::DiagnosticSink& next_;
  LineStarts lines_;
};

bool find_stock_material(LoadedJob& l, core::DiagnosticSink& diags) {
  for (std::size_t i = 0; i < l.materials.size(); ++i) {
    if (l.materials[i].name == l.job.stock.material) {
      l.material = i;
      return true;
    }
  }
  std::string names;
  for (const Material& m : l.materials)
    names += fmt::format("{}{}", names.empty() ? "" : ", ", m.name);
  diags.report({core::Code::JobUnknownMaterial, core::Severity::Error, l.job.stock.material_loc,
                fmt::format("[stock] material \"{}\" is not in {}: give one of {}",
                            l.job.stock.material, l.job.materials, names)});
  return false;
}

}  // namespace

std::optional<LoadedJob> load_job(const std::string& path, core::SourceManager& sources,
                                  core::DiagnosticSink& diags, std::string& io_error) {
  const auto job_text = open(path, sources, io_error);
  if (!job_text) return std::nullopt;
  const std::string folder = std::filesystem::path(path).parent_path().string();
  auto job = read_job(job_text->first, job_text->second, folder, diags);
  if (!job) return std::nullopt;
  LoadedJob l{std::move(*job), {}, {}, 0, std::nullopt};
  const auto tools_text = open(l.job.tools, sources, io_error);
  const auto materials_text = tools_text ? open(l.job.materials, sources, io_error) : std::nullopt;
  if (!materials_text) return std::nullopt;
  auto tools = l.job.tool_table_mm > 0
                   ? read_tool_table_library(*sources.get(tools_text->second), tools_text->second,
                                             l.job.tool_table_mm, diags)
                   : read_tool_library(tools_text->first, tools_text->second, diags);
  auto materials = read_materials(materials_text->first, materials_text->second, diags);
  if (!l.job.machine.empty()) {
    const auto machine_text = open(l.job.machine, sources, io_error);
    if (!machine_text) return std::nullopt;
    LocatedLines located(diags, machine_text->first);
    l.machine = sim::read_machine_profile(machine_text->first, machine_text->second, located);
    if (!l.machine) return std::nullopt;
  }
  if (!tools || !materials) return std::nullopt;
  l.tools = std::move(*tools);
  l.materials = std::move(*materials);
  if (!find_stock_material(l, diags)) return std::nullopt;
  return l;
}

}  // namespace usina::job
