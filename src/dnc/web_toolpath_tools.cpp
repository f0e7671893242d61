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

// The figures need no diagnostics: the check has them.
class Errors final : public core::DiagnosticSink {
 public:
  void report(core::Diagnostic d) override {
    if (d.severity == core::Severity::Error) ++count;
  }

  std::uint64_t count = 0;
};

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
  Errors diags;
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
  out["complete"] = ok && diags.count == 0;
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
  auto program = find_program(c.ctx.store, c.params[0]);
  if (!program)
    return tl::unexpected(
        error_response(c.req, status_of(program.error()), program.error().message));
  auto revision = find_revision(c.ctx.store, c.params[0], c.params[1]);
  if (!revision)
    return tl::unexpected(
        error_response(c.req, status_of(revision.error()), revision.error().message));
  Wanted w;
  w.settings.dialect = program->dialect;
  const auto it = c.ctx.profiles.find(program->machine_class);
  w.settings.profile = it == c.ctx.profiles.end() ? sim::default_machine_profile() : it->second;
  // The class names the profile: the same bytes of two classes time differently.
  w.key =
      "tools " + toolpath_key(revision->hash, program->dialect + "@" + program->machine_class, 0);
  return w;
}

}  // namespace

// Without the service (an Api made without one): computed here, on the loop.
HttpResponse api_tool_figures(ApiCall& c) {
  auto w = wanted(c);
  if (!w) return std::move(w.error());
  auto bytes = revision_bytes(c.ctx.store, c.params[0], c.params[1]);
  if (!bytes) return error_response(c.req, status_of(bytes.error()), bytes.error().message);
  const ToolpathReply reply{c.req.version(), c.req.keep_alive()};
  return computed_response(reply, kJsonType, tool_figures_json(*bytes, w->settings),
                           ToolpathFrom::Computed);
}

void api_tool_figures_later(ApiCall& c, HttpAnswer answer) {
  auto w = wanted(c);
  if (!w) return answer(std::move(w.error()));
  const ToolpathReply reply{c.req.version(), c.req.keep_alive()};
  ToolpathService& service = *c.ctx.toolpaths;
  if (ToolpathStream kept = service.cached(w->key))
    return answer(computed_response(reply, kJsonType, *kept, ToolpathFrom::Cache));
  auto bytes = revision_bytes(c.ctx.store, c.params[0], c.params[1]);
  if (!bytes) return answer(error_response(c.req, status_of(bytes.error()), bytes.error().message));
  service.run(
      w->key,
      [text = std::move(*bytes), settings = std::move(w->settings)] {
        return tool_figures_json(text, settings);
      },
      [reply, answer = std::move(answer)](ToolpathStream s, ToolpathFrom from,
                                          const std::string& error) {
        answer(s ? computed_response(reply, kJsonType, *s, from) : run_failed(reply, error));
      });
}

}  // namespace usina::dnc
