// A machine's utilisation per day and its tool-life counts
// (store_utilisation.hpp), over a range of calendar days given as
// `?from=YYYY-MM-DD&to=YYYY-MM-DD` (both inclusive): UTC days, or with
// `days=local` the days of the machine's shift calendar's zone.
#include <algorithm>
#include <charconv>
#include <chrono>

#include <fmt/format.h>

#include "dnc/api_json.hpp"
#include "dnc/api_router.hpp"
#include "dnc/server_machines.hpp"
#include "dnc/shift_calendar.hpp"
#include "dnc/store_utilisation.hpp"

namespace usina::dnc {
namespace {

namespace chr = std::chrono;

constexpr double kDaySeconds = 86'400.0;
constexpr std::int64_t kMaxDays = 366;

std::string date_text(std::int64_t day) {
  const chr::year_month_day date{chr::sys_days(chr::days(day))};
  return fmt::format("{:04}-{:02}-{:02}", static_cast<int>(date.year()),
                     static_cast<unsigned>(date.month()), static_cast<unsigned>(date.day()));
}

struct DayRange {
  std::int64_t first = 0;
  std::int64_t last = 0;
};

// `from` and `to` of the query; each defaults to `fallback` (a day number).
tl::expected<DayRange, std::string> read_range(const ApiCall& c, std::int64_t from_fallback,
                                               std::int64_t to_fallback) {
  DayRange r{from_fallback, to_fallback};
  for (const auto& [key, into] : {std::pair{"from", &r.first}, std::pair{"to", &r.last}}) {
    const auto it = c.target.query.find(key);
    if (it == c.target.query.end()) continue;
    const auto day = day_number(it->second);
    if (!day)
      return tl::unexpected(
          fmt::format("{} must be a date YYYY-MM-DD, not \"{}\"", key, it->second));
    *into = *day;
  }
  if (r.first > r.last) return tl::unexpected(std::string("from is after to"));
  return r;
}

HttpResponse bad(const ApiCall& c, const std::string& message) {
  return error_response(c.req, http::status::bad_request, message);
}

double seconds(const MachineDay& d, const char* activity) {
  const auto it = d.seconds.find(activity);
  return it == d.seconds.end() ? 0.0 : it->second;
}

nlohmann::json day_json(const MachineDay& d, double elapsed) {
  const double feeding = seconds(d, "feeding");
  const double alarm = seconds(d, "alarm");
  const double down = seconds(d, "down");
  const double length = d.length_seconds();
  // The control's own cycles ran from its memory while the link was idle.
  const double running = std::min(feeding + d.control_cycle_seconds, length);
  const double idle = std::max(0.0, seconds(d, "idle") - d.control_cycle_seconds);
  nlohmann::json out = {{"date", date_text(d.day)},
                        {"running_seconds", running},
                        {"feeding_seconds", feeding},
                        {"control_cycle_seconds", d.control_cycle_seconds},
                        {"transfer_seconds", seconds(d, "transfer")},
                        {"idle_seconds", idle},
                        {"alarm_seconds", alarm},
                        {"link_down_seconds", down},
                        {"unknown_seconds", std::max(0.0, elapsed - d.known_seconds)},
                        {"server_off_seconds", seconds(d, "off")},
                        {"parts", d.parts},
                        {"day_seconds", length},
                        {"utilisation", running / length}};
  out["availability"] = d.known_seconds > 0
                            ? nlohmann::json((d.known_seconds - alarm - down) / d.known_seconds)
                            : nlohmann::json(nullptr);
  return out;
}

// The shift figures of a day, for a machine with a calendar.
void add_shift_figures(nlohmann::json& out, const MachineDay& d) {
  const double running = out["running_seconds"].get<double>();
  const double in_shift = std::min({d.running_in_shift_seconds, running, d.scheduled_seconds});
  out["scheduled_seconds"] = d.scheduled_seconds;
  out["running_in_shift_seconds"] = in_shift;
  out["running_outside_shift_seconds"] = std::max(0.0, running - in_shift);
  out["shift_utilisation"] = d.scheduled_seconds > 0
                                 ? nlohmann::json(in_shift / d.scheduled_seconds)
                                 : nlohmann::json(nullptr);
}

nlohmann::json calendar_json(const ShiftCalendar& c) {
  return {{"timezone", c.timezone},
          {"shifts", c.shifts.size()},
          {"holidays", c.holidays.size()},
          {"source", c.source}};
}

// The seconds of `day` that have passed at `now_us`.
double elapsed_of(const MachineDay& day, std::int64_t now_us) {
  const double since = static_cast<double>(now_us - day.start_us) / 1e6;
  return std::clamp(since, 0.0, day.length_seconds());
}

std::int64_t today(const ApiCall& c) {
  return calendar_date(nullptr, c.ctx.store.now_us());
}

// Whose midnight cuts the days: UTC's (no `days`, or `days=utc`), or with
// `days=local` the zone of the machine's calendar. A machine without a
// calendar has no local midnight to give: 400, rather than UTC days under
// a local name.
struct DayZone {
  const ZoneOffsets* offsets = nullptr;  // nullptr: UTC
  std::string name = "UTC";
  bool local = false;
};

tl::expected<DayZone, std::string> read_day_zone(const ApiCall& c,
                                                 const std::optional<ShiftCalendar>& calendar) {
  const auto it = c.target.query.find("days");
  if (it == c.target.query.end() || it->second == "utc") return DayZone{};
  if (it->second != "local")
    return tl::unexpected(fmt::format("days must be utc or local, not \"{}\"", it->second));
  if (!calendar) {
    return tl::unexpected(fmt::format(
        "days=local cuts the days at midnight in the zone of the machine's shift calendar, and "
        "{} has none: give it one ([calendar] or its own, with a timezone), or leave days out "
        "for UTC days",
        c.params[0]));
  }
  return DayZone{calendar->offsets.get(), calendar->timezone, true};
}

std::string utilisation_basis(const DayZone& zone) {
  if (!zone.local) return "running_seconds / 86400: a 24 h UTC calendar day, not a shift";
  return fmt::format(
      "running_seconds / day_seconds: a calendar day of {} from midnight to midnight (23, 24 or "
      "25 h), not a shift",
      zone.name);
}

}  // namespace

HttpResponse api_utilisation(ApiCall& c) {
  const MachineRuntime* machine = c.ctx.machines.find(c.params[0]);
  if (machine == nullptr)
    return error_response(c.req, http::status::not_found,
                          fmt::format("no machine {}", c.params[0]));
  const std::optional<ShiftCalendar>& calendar = machine->config.calendar;
  auto zone = read_day_zone(c, calendar);
  if (!zone) return bad(c, zone.error());
  const std::int64_t now_day = calendar_date(zone->offsets, c.ctx.store.now_us());
  auto range = read_range(c, now_day, now_day);
  if (!range) return bad(c, range.error());
  if (range->last - range->first + 1 > kMaxDays)
    return bad(c, fmt::format("at most {} days at a time", kMaxDays));
  const std::vector<CalendarDay> spans = calendar_days(zone->offsets, range->first, range->last);
  const TimeSpans shifts =
      calendar ? shift_times(*calendar, spans.front().start_us, spans.back().end_us) : TimeSpans{};
  auto days = machine_days(c.ctx.store, c.params[0], spans, calendar ? &shifts : nullptr);
  if (!days) return error_response(c.req, status_of(days.error()), days.error().message);
  nlohmann::json list = nlohmann::json::array();
  double running = 0.0;
  double length = 0.0;
  double scheduled = 0.0;
  double in_shift = 0.0;
  for (const MachineDay& d : *days) {
    list.push_back(day_json(d, elapsed_of(d, c.ctx.store.now_us())));
    running += list.back()["running_seconds"].get<double>();
    length += d.length_seconds();
    if (!calendar) continue;
    add_shift_figures(list.back(), d);
    scheduled += d.scheduled_seconds;
    in_shift += list.back()["running_in_shift_seconds"].get<double>();
  }
  nlohmann::json out = {
      {"machine", c.params[0]},
      {"from", date_text(range->first)},
      {"to", date_text(range->last)},
      {"days_in", zone->name},
      {"day_seconds", zone->local ? nlohmann::json(nullptr) : nlohmann::json(kDaySeconds)},
      {"utilisation_basis", utilisation_basis(*zone)},
      {"utilisation", running / length},
      {"calendar", calendar ? calendar_json(*calendar) : nlohmann::json(nullptr)},
      {"days", std::move(list)}};
  if (calendar) {
    out["shift_utilisation"] =
        scheduled > 0 ? nlohmann::json(in_shift / scheduled) : nlohmann::json(nullptr);
    out["shift_utilisation_basis"] = fmt::format(
        "running seconds inside the shifts / the shifts' planned seconds, per {} calendar day",
        zone->name);
  }
  return json_response(c.req, http::status::ok, out);
}

namespace {

// Its life from the machine's `tool_life` (null without one): the parts and
// minutes, the share used, and whether it is worn (used 1 or more).
void add_life(nlohmann::json& out, const ToolLives& lives, const ToolUse& t) {
  const auto it = lives.find(t.tool);
  const ToolLifeLimit* life = it == lives.end() ? nullptr : &it->second;
  // A plain double and a flag: GCC 12 thinks an optional's value read under
  // its own test may be uninitialised (-Wmaybe-uninitialized, a false alarm).
  const std::optional<double> share =
      life ? life_used(*life, t.parts, t.cutting_seconds) : std::nullopt;
  const bool has_share = share.has_value();
  const double used = share.value_or(0.0);
  out["life_parts"] = life && life->parts ? nlohmann::json(*life->parts) : nlohmann::json(nullptr);
  out["life_cutting_minutes"] = life && life->cutting_minutes
                                    ? nlohmann::json(*life->cutting_minutes)
                                    : nlohmann::json(nullptr);
  out["life_used"] = has_share ? nlohmann::json(used) : nlohmann::json(nullptr);
  out["worn"] = has_share && used >= 1.0;
}

nlohmann::json tool_json(const ToolUse& t, std::int64_t range_from_us) {
  nlohmann::json out = {{"tool", t.tool},
                        {"parts", t.parts},
                        {"cutting_seconds", t.cutting_seconds},
                        {"cutting_minutes", t.cutting_seconds / 60.0},
                        {"seconds", t.seconds},
                        {"since_us", t.from_reset ? t.reset->at_us : range_from_us},
                        {"counted_from", t.from_reset ? "reset" : "range"},
                        {"reset_at_us", nullptr},
                        {"reset_by", nullptr},
                        {"reset_reason", nullptr}};
  if (t.reset) {
    out["reset_at_us"] = t.reset->at_us;
    out["reset_by"] = t.reset->by;
    out["reset_reason"] = t.reset->reason;
  }
  return out;
}

// "T5" or "5" of the route: the tool number, 0 to kMaxToolNumber.
std::optional<std::int64_t> tool_number(std::string_view text) {
  if (!text.empty() && (text.front() == 'T' || text.front() == 't')) text.remove_prefix(1);
  std::int64_t n = -1;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size() || n < 0 ||
      n > kMaxToolNumber)
    return std::nullopt;
  return n;
}

}  // namespace

HttpResponse api_tool_life(ApiCall& c) {
  const MachineRuntime* machine = c.ctx.machines.find(c.params[0]);
  if (machine == nullptr)
    return error_response(c.req, http::status::not_found,
                          fmt::format("no machine {}", c.params[0]));
  // Without a range: every part the store knows of, up to today, each tool
  // counted from its last reset; with `from`, every tool from that day.
  auto range = read_range(c, 0, today(c));
  if (!range) return bad(c, range.error());
  const bool from_resets = !c.target.query.contains("from");
  const std::int64_t day_us = 86'400'000'000;
  const std::int64_t from_us = range->first * day_us;
  auto life = tool_life(c.ctx.store, c.params[0], from_us, (range->last + 1) * day_us, from_resets);
  if (!life) return error_response(c.req, status_of(life.error()), life.error().message);
  // A tool with a life that has cut nothing counted yet is listed too, at 0.
  const ToolLives& lives = machine->config.tool_life;
  std::vector<ToolUse> uses = std::move(life->tools);
  for (const auto& [tool, limit] : lives) {
    (void)limit;
    const bool listed =
        std::any_of(uses.begin(), uses.end(), [&](const ToolUse& u) { return u.tool == tool; });
    if (!listed) {
      ToolUse unused;
      unused.tool = static_cast<int>(tool);
      uses.push_back(unused);
    }
  }
  std::sort(uses.begin(), uses.end(),
            [](const ToolUse& a, const ToolUse& b) { return a.tool < b.tool; });
  nlohmann::json tools = nlohmann::json::array();
  for (const ToolUse& t : uses) {
    tools.push_back(tool_json(t, from_us));
    add_life(tools.back(), lives, t);
  }
  return json_response(c.req, http::status::ok,
                       {{"machine", c.params[0]},
                        {"from", date_text(range->first)},
                        {"to", date_text(range->last)},
                        {"parts", life->parts},
                        {"parts_without_program", life->parts_without_program},
                        {"parts_without_tool_list", life->parts_without_tools},
                        {"tools", std::move(tools)}});
}

HttpResponse api_reset_tool(ApiCall& c) {
  if (c.ctx.machines.find(c.params[0]) == nullptr)
    return error_response(c.req, http::status::not_found,
                          fmt::format("no machine {}", c.params[0]));
  const auto tool = tool_number(c.params[1]);
  if (!tool) {
    return bad(c, fmt::format("the tool must be a whole number from 0 to {} (T5 or 5), not \"{}\"",
                              kMaxToolNumber, c.params[1]));
  }
  std::string reason;
  if (!c.req.body().empty()) {  // the body, and its reason, are optional
    auto body = json_body(c.req);
    if (!body) return bad(c, body.error());
    auto given = string_field(*body, "reason", false);
    if (!given) return bad(c, given.error());
    reason = given->value_or("");
  }
  auto reset = reset_tool(c.ctx.store, c.actor(), c.params[0], *tool, reason);
  if (!reset) return error_response(c.req, status_of(reset.error()), reset.error().message);
  const nlohmann::json answer = {{"machine", c.params[0]},
                                 {"tool", reset->tool},
                                 {"reset_at_us", reset->at_us},
                                 {"reset_by", reset->by},
                                 {"reset_reason", reset->reason}};
  c.ctx.events.publish("machine.tool_reset", answer);
  return json_response(c.req, http::status::ok, answer);
}

}  // namespace usina::dnc
