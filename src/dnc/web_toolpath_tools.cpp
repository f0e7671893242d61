// GET /api/programs/{name}/revisions/{rev}/tools: the figures of each tool
// (web_toolpath_tools.hpp), on the tool-path service's pool.
#include "dnc/web_toolpath_tools.hpp"

#include <nlohmann/json.hpp>

#include "canon/sink.hpp"
#include "core/source.hpp"
#include "dnc/api_router.hpp"
#include "dnc/store_revisions.hpp"
#include "dnc/web_toolpath_api.hpp"
#include "dnc/web_toolpath_cache.hpp"
#include "dnc/web_toolpath_service.hpp"
#include "gcode/dialect.hpp"
#include "sim/stats.hpp"

namespace usina::dnc {
namespace {

using nlohmann::json;

json tool_json(const sim::ToolStats& t) {
  return {{"tool", t.tool},         {"total_s", t.total_s()},   {"cutting_s", t.cutting_s},
          {"rapid_s", t.rapid_s},   {"other_s", t.other_s},     {"cutting_mm", t.cutting_mm},
          {"rapid_mm", t.rapid_mm}, {"moves", t.counts.moves()}};
}

constexpr std::string_view kJsonType = "application/json";

}  // namespace

std::string tool_figures_json(std::string_view text, const ToolFiguresSettings& settings) {
  json out = {{"machine", settings.profile.name}, {"complete", false}, {"tools", json::array()}};
  const gcode::Dialect* dialect = gcode::find_dialect(settings.dialect);
  if (dialect == nullptr) return out.dump();
  core::ErrorCount diags;
  core::SourceManager sources;
  const std::uint32_t id =
      sources.add(core::SourceFile::from_string("<revision>", std::string(text)));
  sim::StatsSink stats(settings.profile, sim::StatsOptions{}, diags);
  canon::OpBudget budget(stats, settings.max_ops, diags);
  auto runner = dialect->make_runner(gcode::RunContext{
      sources, gcode::InterpOptions{}, gcode::default_options(*dialect), budget, diags});
  const bool ok = runner->run(id);
  stats.finish();
  const sim::StatsReport report = stats.report();
  out["complete"] = ok && diags.errors() == 0;
  for (const sim::ToolStats& t : report.tools)
    out["tools"].push_back(tool_json(t));
  out["total"] = tool_json(report.total);
  return out.dump(-1, ' ', false, json::error_handler_t::replace);
}

namespace {

struct Wanted {
  ToolFiguresSettings settings;
  std::string key;
};

tl::expected<Wanted, HttpResponse> wanted(ApiCall& c) {
  auto named = named_revision(c);
  if (!named) return tl::unexpected(std::move(named.error()));
  const Program& program = named->program;
  Wanted w;
  w.settings.dialect = program.dialect;
  const auto it = c.ctx.profiles.find(program.machine_class);
  w.settings.profile = it == c.ctx.profiles.end() ? sim::default_machine_profile() : it->second;
  // The class names the profile: the same bytes of two classes time differently.
  w.key = "tools " +
          toolpath_key(named->revision.hash, program.dialect + "@" + program.machine_class, 0);
  return w;
}

RevisionWork figures_work(ToolFiguresSettings settings) {
  return [settings = std::move(settings)](const std::string& text) {
    return tool_figures_json(text, settings);
  };
}

}  // namespace

// Without the service (an Api made without one): computed here, on the loop.
HttpResponse api_tool_figures(ApiCall& c) {
  auto w = wanted(c);
  if (!w) return std::move(w.error());
  return answer_now(c, kJsonType, figures_work(w->settings));
}

void api_tool_figures_later(ApiCall& c, HttpAnswer answer) {
  auto w = wanted(c);
  if (!w) return answer(std::move(w.error()));
  answer_later(c, std::move(answer), w->key, kJsonType, figures_work(std::move(w->settings)));
}

}  // namespace usina::dnc
