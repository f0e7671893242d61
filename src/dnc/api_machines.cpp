// Machines and their jobs: a machine's state with its running job's
// progress, part count and last cycle time; a job queued (send or drip);
// a job's state, bytes, block and the hash of what went on the wire.
#include <charconv>

#include <fmt/format.h>

#include "dnc/api_json.hpp"
#include "dnc/api_router.hpp"
#include "dnc/machine_settings.hpp"
#include "dnc/resume.hpp"
#include "dnc/store_check.hpp"
#include "dnc/store_jobs.hpp"
#include "dnc/store_revisions.hpp"
#include "dnc/store_sheets.hpp"

namespace usina::dnc {
namespace {

HttpResponse store_failure(const ApiCall& c, const StoreError& e) {
  return error_response(c.req, status_of(e), e.message);
}

HttpResponse bad(const ApiCall& c, const std::string& message) {
  return error_response(c.req, http::status::bad_request, message);
}

HttpResponse no_machine(const ApiCall& c) {
  return error_response(c.req, http::status::not_found, fmt::format("no machine {}", c.params[0]));
}

// What goes down to the machine with a job (seed 004 table 7.3): the time
// the revision's check expects, its tools in order with their times, and
// its setup sheets. Null and empty for what the store does not hold.
nlohmann::json with_downward(Store& store, const JobRecord& j) {
  nlohmann::json out = job_json(j);
  out["expected_cycle_s"] = nullptr;
  out["tools"] = nlohmann::json::array();
  out["sheets"] = nlohmann::json::array();
  if (auto r = find_revision(store, j.program, j.revision)) {
    if (const auto check = CheckResults::from_json(r->checks_json)) {
      out["expected_cycle_s"] = check->cycle_time_s;
      for (const CheckTool& t : check->tools)
        out["tools"].push_back({{"tool", t.tool}, {"total_s", t.total_s}});
    }
  }
  if (auto sheets = list_sheets(store, j.program, j.revision)) {
    for (const Sheet& s : *sheets)
      out["sheets"].push_back(sheet_json(s));
  }
  return out;
}

// The machine's newest job, when it ended in an alarm (the control's XOFF
// never released, the link lost...): the page shows it until another job
// runs. Null otherwise.
nlohmann::json last_alarm(Store& store, const std::string& machine) {
  auto newest = list_jobs(store, machine, 1);
  if (!newest || newest->empty() || !newest->front().alarm) return nullptr;
  const JobRecord& j = newest->front();
  return {{"job", j.id}, {"reason", j.reason}, {"at_us", j.ended_at_us}};
}

tl::expected<JobOrder, std::string> read_order(const HttpRequest& req) {
  auto body = json_body(req);
  if (!body) return tl::unexpected(body.error());
  JobOrder order;
  auto program = string_field(*body, "program", true);
  if (!program) return tl::unexpected(program.error());
  order.program = **program;
  auto revision = string_field(*body, "revision", false);
  if (!revision) return tl::unexpected(revision.error());
  order.revision = revision->value_or("");
  auto mode = string_field(*body, "mode", true);
  if (!mode) return tl::unexpected(mode.error());
  if (**mode != "send" && **mode != "drip")
    return tl::unexpected(fmt::format("mode must be \"send\" or \"drip\", not \"{}\"", **mode));
  order.mode = **mode == "drip" ? JobMode::Drip : JobMode::Send;
  return order;
}

// start_block: a line of the file (a number, or "120") or an N word
// ("N120"); start_tool: the first change to that tool (docs/resume.md).
tl::expected<std::optional<gcode::ResumeStart>, std::string> read_start(const HttpRequest& req) {
  const auto body = nlohmann::json::parse(req.body(), nullptr, false);
  const bool block = body.contains("start_block") && !body["start_block"].is_null();
  const bool tool = body.contains("start_tool") && !body["start_tool"].is_null();
  if (block && tool) return tl::unexpected(std::string("give start_block or start_tool, not both"));
  if (tool) {
    auto n = count_field(body, "start_tool");
    if (!n) return tl::unexpected(n.error());
    return gcode::ResumeStart{gcode::ResumeStart::Kind::Tool, static_cast<long>(**n)};
  }
  if (!block) return std::nullopt;
  const auto& v = body["start_block"];
  std::optional<gcode::ResumeStart> start;
  if (v.is_number_unsigned()) {
    start = gcode::ResumeStart{gcode::ResumeStart::Kind::Line, v.get<long>()};
  } else if (v.is_string()) {
    start = gcode::parse_start_block(v.get<std::string>());
  }
  if (!start)
    return tl::unexpected(
        std::string("start_block must be a line number (120) or an N word (\"N120\")"));
  return start;
}

// The restart program of the revision, or why there is none (a 400).
tl::expected<std::shared_ptr<const std::string>, std::string> restart_text(
    ApiCall& c, const JobOrder& order, const gcode::ResumeStart& start) {
  auto program = find_program(c.ctx.store, order.program);
  if (!program) return tl::unexpected(program.error().message);
  auto bytes = revision_bytes(c.ctx.store, order.program, order.revision);
  if (!bytes) return tl::unexpected(bytes.error().message);
  auto text = resume_program(*bytes, program->dialect, start);
  if (!text) return tl::unexpected(text.error());
  return std::make_shared<const std::string>(std::move(*text));
}

std::optional<std::int64_t> job_id(const std::string& s) {
  std::int64_t id = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), id);
  if (ec != std::errc() || end != s.data() + s.size() || id <= 0) return std::nullopt;
  return id;
}

}  // namespace

nlohmann::json machine_json(ApiCall& c, MachineRuntime& m) {
  const LinkConfig& l = m.config.link;
  nlohmann::json out = {{"name", l.name},
                        {"dialect", l.dialect},
                        {"machine_class", m.config.machine_class},
                        {"mode", mode_name(l.mode)},
                        {"code", code_name(l.code)},
                        {"port", l.port},
                        {"state", m.station ? station_state_name(m.station->state()) : "offline"},
                        {"link_error", m.link_error},
                        {"queue", m.queue},
                        {"job", nullptr}};
  if (m.current) {
    if (auto live = c.ctx.machines.job(m.current->id))
      out["job"] = with_downward(c.ctx.store, *live);
  }
  out["alarm"] = last_alarm(c.ctx.store, l.name);
  out.update(parts_json(c.ctx.store, m));  // server_mdc.cpp
  out["part_count_source"] = "drip feeds run to their end, and the control's part lines";
  // Where it is set: the file's machines are changed in the file, the
  // page's from the page (api_machine_admin.cpp).
  out["source"] = m.config.from_store ? "api" : "file";
  out["settings"] = machine_settings(m.config);
  return out;
}

HttpResponse api_list_machines(ApiCall& c) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& m : c.ctx.machines.all())
    out.push_back(machine_json(c, *m));
  nlohmann::json answer = {{"machines", std::move(out)}};
  const auto it = c.target.query.find("retired");
  if (it != c.target.query.end() && it->second == "1") {
    auto retired = retired_machines(c);
    if (!retired) return error_response(c.req, status_of(retired.error()), retired.error().message);
    answer["retired"] = std::move(*retired);
  }
  return json_response(c.req, http::status::ok, answer);
}

HttpResponse api_machine(ApiCall& c) {
  MachineRuntime* m = c.ctx.machines.find(c.params[0]);
  if (m == nullptr) return no_machine(c);
  return json_response(c.req, http::status::ok, machine_json(c, *m));
}

HttpResponse api_start_job(ApiCall& c) {
  MachineRuntime* m = c.ctx.machines.find(c.params[0]);
  if (m == nullptr) return no_machine(c);
  auto order = read_order(c.req);
  if (!order) return bad(c, order.error());
  auto start = read_start(c.req);
  if (!start) return bad(c, start.error());
  if (order->revision.empty()) {
    auto released = released_revision(c.ctx.store, order->program);
    if (!released) return store_failure(c, released.error());
    if (!*released) {
      return error_response(c.req, http::status::conflict,
                            fmt::format("{} has no released revision; give one", order->program));
    }
    order->revision = (*released)->hash;
  }
  if (*start) {
    if (auto ok = c.ctx.machines.may_take(*m, *order); !ok) return store_failure(c, ok.error());
    auto text = restart_text(c, *order, **start);
    if (!text) return bad(c, text.error());
    order->restart = *text;
  }
  auto job = c.ctx.machines.submit(*m, *order, c.actor());
  if (!job) return store_failure(c, job.error());
  nlohmann::json out = job_json(*job);
  return json_response(c.req, http::status::created, out);
}

HttpResponse api_job(ApiCall& c) {
  const auto id = job_id(c.params[0]);
  if (!id) return error_response(c.req, http::status::not_found, "no such job");
  auto job = c.ctx.machines.job(*id);
  if (!job) return store_failure(c, job.error());
  return json_response(c.req, http::status::ok, with_downward(c.ctx.store, *job));
}

HttpResponse api_stop_job(ApiCall& c) {
  const auto id = job_id(c.params[0]);
  if (!id) return error_response(c.req, http::status::not_found, "no such job");
  auto job = c.ctx.machines.job(*id);
  if (!job) return store_failure(c, job.error());
  MachineRuntime* m = c.ctx.machines.find(job->machine);
  if (m != nullptr && job->state == "queued") {
    // Not started: it leaves the queue now, with nothing sent.
    auto cancelled = c.ctx.machines.cancel_queued(
        *m, *id, fmt::format("stopped by {} before it started", c.actor().user), c.actor());
    if (!cancelled) return store_failure(c, cancelled.error());
    return json_response(c.req, http::status::ok, job_json(*cancelled));
  }
  if (m == nullptr || !m->current || m->current->id != *id) {
    return error_response(c.req, http::status::conflict,
                          fmt::format("job {} is {}, not running or queued", *id, job->state));
  }
  m->station->stop_job(fmt::format("stopped by {}", c.actor().user));
  return json_response(c.req, http::status::accepted, job_json(*job));
}

}  // namespace usina::dnc
