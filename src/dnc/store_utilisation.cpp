#include "dnc/store_utilisation.hpp"

#include <algorithm>

#include "dnc/store_check.hpp"
#include "dnc/store_parts.hpp"

namespace usina::dnc {
namespace {

// The index of the day holding the instant `us` (days.size() past the last).
std::size_t day_at(const std::vector<MachineDay>& days, std::int64_t us) {
  const auto after =
      std::upper_bound(days.begin(), days.end(), us,
                       [](std::int64_t t, const MachineDay& d) { return t < d.start_us; });
  return after == days.begin() ? days.size() : static_cast<std::size_t>(after - days.begin() - 1);
}

struct Change {
  std::int64_t at_us;
  std::string activity;
};

// The changes in [from, to), with the one in force at `from` first (at `from`).
StoreResult<std::vector<Change>> changes(Store& store, std::string_view machine,
                                         std::int64_t from_us, std::int64_t to_us) {
  std::vector<Change> out;
  auto before = store.db().query(
      "SELECT activity FROM machine_activity WHERE machine = $1 AND at < $2 "
      "ORDER BY at DESC, id DESC LIMIT 1",
      {machine, from_us});
  if (!before) return tl::unexpected(before.error());
  if (!before->empty()) out.push_back({from_us, before->front().text(0)});
  auto rows = store.db().query(
      "SELECT at, activity FROM machine_activity WHERE machine = $1 AND at >= $2 AND at < $3 "
      "ORDER BY at, id",
      {machine, from_us, to_us});
  if (!rows) return tl::unexpected(rows.error());
  for (const SqlRow& r : *rows)
    out.push_back({r.integer(0), r.text(1)});
  return out;
}

// The microseconds of [a, b) inside `spans`.
std::int64_t inside(const TimeSpans* spans, std::int64_t a, std::int64_t b) {
  if (spans == nullptr) return 0;
  std::int64_t total = 0;
  for (const auto& [lo, hi] : *spans)
    total += std::max<std::int64_t>(0, std::min(b, hi) - std::max(a, lo));
  return total;
}

// Adds [a, b) spent in `activity` to the days it covers.
void spread(std::vector<MachineDay>& days, std::int64_t a, std::int64_t b,
            const std::string& activity, const TimeSpans* shifts) {
  if (days.empty() || b <= a) return;
  a = std::max(a, days.front().start_us);
  for (std::size_t i = day_at(days, a); i < days.size() && days[i].start_us < b; ++i) {
    const std::int64_t lo = std::max(a, days[i].start_us);
    const std::int64_t hi = std::min(b, days[i].end_us);
    if (hi <= lo) continue;
    const double s = static_cast<double>(hi - lo) / 1e6;
    if (activity != "off") days[i].known_seconds += s;
    days[i].seconds[activity] += s;
    if (activity == "feeding")
      days[i].running_in_shift_seconds += static_cast<double>(inside(shifts, lo, hi)) / 1e6;
  }
}

// The drip feeds done in [from, to): (ended at, program, revision).
StoreResult<SqlRows> drip_parts(Store& store, std::string_view machine, std::int64_t from_us,
                                std::int64_t to_us) {
  return store.db().query(
      "SELECT ended_at, program, revision FROM jobs WHERE machine = $1 AND mode = 'drip' AND "
      "state = 'done' AND ended_at >= $2 AND ended_at < $3 ORDER BY id",
      {machine, from_us, to_us});
}

}  // namespace

StoreResult<void> record_activity(Store& store, std::string_view machine, std::string_view activity,
                                  std::int64_t at_us) {
  Transaction tx(store.db());
  if (auto b = tx.begin_write(); !b) return b;
  auto r =
      store.db().query("INSERT INTO machine_activity (machine, activity, at) VALUES ($1, $2, $3)",
                       {machine, activity, at_us});
  if (!r) return tl::unexpected(r.error());
  return tx.commit();
}

StoreResult<void> record_heartbeat(Store& store, std::int64_t at_us) {
  Transaction tx(store.db());
  if (auto b = tx.begin_write(); !b) return b;
  // SQLite (3.24 on) and PostgreSQL both spell the upsert this way.
  auto r = store.db().query(
      "INSERT INTO server_heartbeat (server, at) VALUES ('usina', $1) "
      "ON CONFLICT (server) DO UPDATE SET at = excluded.at",
      {at_us});
  if (!r) return tl::unexpected(r.error());
  return tx.commit();
}

StoreResult<std::optional<std::int64_t>> last_heartbeat(Store& store) {
  auto rows = store.db().query("SELECT at FROM server_heartbeat WHERE server = 'usina'", {});
  if (!rows) return tl::unexpected(rows.error());
  if (rows->empty()) return std::optional<std::int64_t>{};
  return std::optional<std::int64_t>(rows->front().integer(0));
}

StoreResult<std::int64_t> close_activity_of_dead_server(Store& store) {
  auto beat = last_heartbeat(store);
  if (!beat) return tl::unexpected(beat.error());
  // Each machine's last activity (the latest time, the latest row of it).
  auto rows = store.db().query(
      "SELECT a.machine, a.activity, a.at FROM machine_activity a WHERE a.id = "
      "(SELECT b.id FROM machine_activity b WHERE b.machine = a.machine "
      "ORDER BY b.at DESC, b.id DESC LIMIT 1)",
      {});
  if (!rows) return tl::unexpected(rows.error());
  std::int64_t closed = 0;
  for (const SqlRow& r : *rows) {
    if (r.text(1) == "off") continue;
    const std::int64_t at = std::max(r.integer(2), beat->value_or(r.integer(2)));
    if (auto w = record_activity(store, r.text(0), "off", at); !w) return tl::unexpected(w.error());
    ++closed;
  }
  return closed;
}

StoreResult<std::vector<MachineDay>> machine_days(Store& store, std::string_view machine,
                                                  std::int64_t first_day, std::int64_t last_day,
                                                  const TimeSpans* shifts) {
  return machine_days(store, machine, calendar_days(nullptr, first_day, last_day), shifts);
}

StoreResult<std::vector<MachineDay>> machine_days(Store& store, std::string_view machine,
                                                  const std::vector<CalendarDay>& calendar,
                                                  const TimeSpans* shifts) {
  std::vector<MachineDay> days;
  for (const CalendarDay& c : calendar) {
    MachineDay d;
    d.day = c.date;
    d.start_us = c.start_us;
    d.end_us = c.end_us;
    d.scheduled_seconds = static_cast<double>(inside(shifts, c.start_us, c.end_us)) / 1e6;
    days.push_back(std::move(d));
  }
  if (days.empty()) return days;
  const std::int64_t from = days.front().start_us;
  const std::int64_t to = std::min(days.back().end_us, store.now_us());
  if (to <= from) return days;
  auto list = changes(store, machine, from, to);
  if (!list) return tl::unexpected(list.error());
  for (std::size_t i = 0; i < list->size(); ++i) {
    const std::int64_t end = i + 1 < list->size() ? (*list)[i + 1].at_us : to;
    spread(days, (*list)[i].at_us, end, (*list)[i].activity, shifts);
  }
  auto drips = drip_parts(store, machine, from, to);
  if (!drips) return tl::unexpected(drips.error());
  for (const SqlRow& r : *drips)
    if (const std::size_t i = day_at(days, r.integer(0)); i < days.size()) ++days[i].parts;
  auto control = control_parts(store, machine, from, to);
  if (!control) return tl::unexpected(control.error());
  for (const ControlPart& p : *control) {
    const std::size_t i = day_at(days, p.at_us);
    if (i >= days.size()) continue;
    MachineDay& day = days[i];
    ++day.parts;
    if (!p.cycle_us) continue;
    day.control_cycle_seconds += static_cast<double>(*p.cycle_us) / 1e6;
    const std::int64_t began = std::max(p.at_us - *p.cycle_us, day.start_us);
    day.running_in_shift_seconds += static_cast<double>(inside(shifts, began, p.at_us)) / 1e6;
  }
  return days;
}

namespace {

// A revision's tool list from its stored check; nothing when the check
// kept none (or the revision is gone).
StoreResult<std::optional<std::vector<CheckTool>>> tools_of(Store& store,
                                                            const std::string& program,
                                                            const std::string& revision) {
  auto rows = store.db().query("SELECT checks FROM revisions WHERE program = $1 AND hash = $2",
                               {std::string_view(program), std::string_view(revision)});
  if (!rows) return tl::unexpected(rows.error());
  if (rows->empty()) return std::optional<std::vector<CheckTool>>{};
  const auto check = CheckResults::from_json(rows->front().text(0));
  if (!check || !check->has_tools) return std::optional<std::vector<CheckTool>>{};
  return std::optional<std::vector<CheckTool>>(check->tools);
}

}  // namespace

namespace {

struct MadePart {
  std::int64_t at_us;
  std::string program;
  std::string revision;
};

// The parts made in [from, to): drip feeds done, then the control's part lines.
StoreResult<std::vector<MadePart>> parts_made(Store& store, std::string_view machine,
                                              std::int64_t from_us, std::int64_t to_us) {
  std::vector<MadePart> made;
  auto drips = drip_parts(store, machine, from_us, to_us);
  if (!drips) return tl::unexpected(drips.error());
  for (const SqlRow& r : *drips)
    made.push_back({r.integer(0), r.text(1), r.text(2)});
  auto control = control_parts(store, machine, from_us, to_us);
  if (!control) return tl::unexpected(control.error());
  for (const ControlPart& p : *control)
    made.push_back({p.at_us, p.program, p.revision});
  return made;
}

using ToolLists =
    std::map<std::pair<std::string, std::string>, std::optional<std::vector<CheckTool>>>;

// The tool list of a part's revision, read once per revision.
StoreResult<const std::optional<std::vector<CheckTool>>*> tool_list(Store& store, ToolLists& known,
                                                                    const MadePart& part) {
  const auto key = std::pair{part.program, part.revision};
  auto it = known.find(key);
  if (it == known.end()) {
    auto tools = tools_of(store, part.program, part.revision);
    if (!tools) return tl::unexpected(tools.error());
    it = known.emplace(key, std::move(*tools)).first;
  }
  return &it->second;
}

}  // namespace

StoreResult<ToolLife> tool_life(Store& store, std::string_view machine, std::int64_t from_us,
                                std::int64_t to_us, bool from_resets) {
  auto made = parts_made(store, machine, from_us, to_us);
  if (!made) return tl::unexpected(made.error());
  auto resets = last_tool_resets(store, machine, to_us - 1);
  if (!resets) return tl::unexpected(resets.error());
  ToolLife life;
  ToolLists known;
  std::map<int, ToolUse> by_tool;
  for (const auto& [tool, reset] : *resets) {
    ToolUse& use = by_tool[static_cast<int>(tool)];
    use.tool = static_cast<int>(tool);
    use.reset = reset;
    use.from_reset = from_resets && reset.at_us >= from_us;
  }
  for (const MadePart& part : *made) {
    ++life.parts;
    if (part.program.empty()) {
      ++life.parts_without_program;
      continue;
    }
    auto tools = tool_list(store, known, part);
    if (!tools) return tl::unexpected(tools.error());
    if (!**tools) {
      ++life.parts_without_tools;
      continue;
    }
    for (const CheckTool& t : ***tools) {
      ToolUse& use = by_tool[t.tool];
      use.tool = t.tool;
      // A part made before the tool's reset was cut by the insert it replaced.
      if (use.from_reset && part.at_us < use.reset->at_us) continue;
      ++use.parts;
      use.cutting_seconds += t.cutting_s;
      use.seconds += t.total_s;
    }
  }
  for (auto& [tool, use] : by_tool)
    life.tools.push_back(use);
  return life;
}

}  // namespace usina::dnc
