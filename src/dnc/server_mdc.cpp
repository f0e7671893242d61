// Machine data the control punches while idle, as CIMCO's MDC reads it:
// DPRNT lines such as `PART COUNT 12` or `CYCLE TIME 83.4` matched by the
// machine's patterns, and `(MSG, ...)` comments. A punch without an O
// number is read this way; when nothing in it matches, it is refused as a
// program without a name, as before.
#include <cmath>
#include <regex>

#include <fmt/format.h>

#include "dnc/server_machines.hpp"
#include "dnc/store_parts.hpp"

namespace usina::dnc {
namespace {

std::optional<std::regex> compiled(const std::string& pattern) {
  if (pattern.empty() || pattern.size() > kMaxDataPatternLength) return std::nullopt;
  try {
    return std::regex(pattern, kDataPatternFlags);
  } catch (const std::regex_error&) {
    return std::nullopt;
  }
}

// `(MSG, TEXT)` or `(MSG TEXT)`: the text.
std::optional<std::string> message_of(std::string_view line) {
  const std::size_t at = line.find("(MSG");
  if (at == std::string_view::npos) return std::nullopt;
  std::string_view text = line.substr(at + 4);
  if (const std::size_t close = text.rfind(')'); close != std::string_view::npos)
    text = text.substr(0, close);
  while (!text.empty() && (text.front() == ',' || text.front() == ' '))
    text.remove_prefix(1);
  return std::string(text);
}

std::optional<double> number(const std::smatch& m) {
  if (m.size() < 2 || !m[1].matched) return std::nullopt;
  try {
    return std::stod(m[1].str());
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

std::optional<std::int64_t> micros(const std::optional<double>& seconds) {
  // A figure past a year is no cycle time (and would not fit the column).
  if (!seconds || !std::isfinite(*seconds) || *seconds < 0 || *seconds > 366.0 * 86400)
    return std::nullopt;
  return static_cast<std::int64_t>(std::llround(*seconds * 1e6));
}

}  // namespace

void Machines::load_reports(MachineRuntime& m) {
  auto t = control_totals(store_, m.config.link.name);
  if (!t) {
    events_.publish("server.error",
                    {{"machine", m.config.link.name}, {"error", t.error().message}});
    return;
  }
  ControlReports& c = m.reported;
  c.parts = t->parts;
  c.control_count = t->control_count;
  if (t->last_cycle_us) c.last_cycle_seconds = static_cast<double>(*t->last_cycle_us) / 1e6;
  c.last_part_at_us = t->last_part_at_us;
  c.last_message = t->last_message;
}

// Writes what the control said; a store that fails is a `server.error` event
// (the count in memory still moves, the next restart will not have it).
void Machines::keep(const MachineRuntime& m, StoreResult<void> written) {
  if (!written) {
    events_.publish("server.error",
                    {{"machine", m.config.link.name}, {"error", written.error().message}});
  }
}

nlohmann::json parts_json(Store& store, const MachineRuntime& m) {
  nlohmann::json out;
  const ControlReports& c = m.reported;
  auto drip = machine_part_count(store, m.config.link.name);
  const std::int64_t drip_parts = drip ? drip->parts : 0;
  out["part_count"] = drip_parts + c.parts;
  out["control_part_count"] = c.control_count ? nlohmann::json(*c.control_count) : nullptr;
  std::optional<double> cycle = drip ? drip->last_cycle_seconds : std::nullopt;
  const std::int64_t drip_at = drip ? drip->last_run_at_us : 0;
  if (c.last_cycle_seconds && c.last_part_at_us >= drip_at) cycle = c.last_cycle_seconds;
  out["last_cycle_seconds"] = cycle ? nlohmann::json(*cycle) : nullptr;
  out["last_program"] = drip ? drip->last_program : "";
  out["last_run_at_us"] = std::max(drip_at, c.last_part_at_us);
  out["last_message"] = c.last_message;
  return out;
}

bool Machines::machine_data(MachineRuntime& m, const ReceivedProgram& r) {
  if (!r.name.empty()) return false;  // a program
  const auto part = compiled(m.config.part_count_pattern);
  const auto cycle = compiled(m.config.cycle_time_pattern);
  const std::string& machine = m.config.link.name;
  ControlReports& c = m.reported;
  bool any = false;
  std::optional<double> printed_cycle;
  std::size_t start = 0;
  while (start < r.text.size()) {
    std::size_t end = r.text.find('\n', start);
    if (end == std::string::npos) end = r.text.size();
    const std::string line = r.text.substr(start, end - start);
    start = end + 1;
    std::smatch got;
    if (auto text = message_of(line)) {
      any = true;
      c.last_message = *text;
      keep(m, record_control_message(store_, machine, *text, store_.now_us()));
      events_.publish("machine.message", {{"machine", machine}, {"text", *text}});
    } else if (line.size() > kMaxDataLineLength) {
      continue;  // no DPRNT line, and std::regex would recurse once a character
    } else if (cycle && std::regex_search(line, got, *cycle)) {
      any = true;
      printed_cycle = number(got);
    } else if (part && std::regex_search(line, got, *part)) {
      any = true;
      const std::int64_t now = store_.now_us();
      ++c.parts;
      if (auto n = number(got)) c.control_count = static_cast<std::int64_t>(*n);
      // The control's own figure, or the time since its last part line.
      if (printed_cycle) {
        c.last_cycle_seconds = printed_cycle;
      } else if (c.last_part_at_us > 0) {
        c.last_cycle_seconds = static_cast<double>(now - c.last_part_at_us) / 1e6;
      }
      printed_cycle.reset();
      c.last_part_at_us = now;
      keep(m, record_control_part(store_, ControlPart{machine, now, micros(c.last_cycle_seconds),
                                                      c.control_count, "", ""}));
      nlohmann::json e = parts_json(store_, m);
      e["machine"] = machine;
      e["source"] = "control";
      events_.publish("machine.part", std::move(e));
    }
  }
  if (printed_cycle) {  // a cycle line without a part line: the last part's
    c.last_cycle_seconds = printed_cycle;
    if (const auto us = micros(printed_cycle); us && c.parts > 0)
      keep(m, set_last_control_cycle(store_, machine, *us));
  }
  return any;
}

}  // namespace usina::dnc
