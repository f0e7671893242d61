#include "dnc/mtconnect_items.hpp"

#include <chrono>

#include <fmt/chrono.h>
#include <fmt/format.h>

namespace usina::dnc {
namespace {

constexpr std::string_view kUnavailable = "UNAVAILABLE";

std::string text_of(const nlohmann::json& j, const char* key) {
  const auto it = j.find(key);
  return it != j.end() && it->is_string() ? it->get<std::string>() : std::string();
}

// A job that ended other than done: the operator's stop, or a cut-off feed.
std::string ended_execution(const nlohmann::json& job) {
  return text_of(job, "reason").find("stopped by") != std::string::npos ? "STOPPED" : "INTERRUPTED";
}

void apply_job(std::string_view type, const nlohmann::json& e, MachineItems& m) {
  const bool drip = text_of(e, "mode") == "drip";
  if (type == "job.running") {
    m.program = text_of(e, "program");
    if (drip) m.execution = "ACTIVE";
    m.line = -1;
  } else if (type == "job.progress" && drip) {
    m.line = e.value("line", std::int64_t{-1});
  } else if (type == "job.done" && drip) {
    m.execution = "READY";
    m.line = e.value("line", m.line);
  } else if (type == "job.interrupted" || type == "job.failed") {
    if (drip && type == "job.interrupted") m.execution = ended_execution(e);
    m.message = text_of(e, "reason");
  }
}

}  // namespace

std::string shdr_value(std::string_view value) {
  std::string out;
  bool pipe = false;
  for (const char c : value) {
    if (c == '\n' || c == '\r') {
      out += ' ';
    } else if (c == '|') {
      out += "\\|";
      pipe = true;
    } else {
      out += c;
    }
  }
  return pipe ? "\"" + out + "\"" : out;
}

std::string shdr_timestamp() {
  const auto now = std::chrono::system_clock::now();
  const auto seconds = std::chrono::time_point_cast<std::chrono::seconds>(now);
  const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(now - seconds).count();
  return fmt::format("{:%Y-%m-%dT%H:%M:%S}.{:03}Z", seconds, ms);
}

void MtconnectItems::add_machine(const std::string& name, const MachineItems& start) {
  machines_[name] = start;
}

std::vector<ShdrItem> MtconnectItems::render(const std::string& name, const MachineItems& m) const {
  const auto or_unavailable = [&](std::string v) {
    return m.available && !v.empty() ? shdr_value(v) : std::string(kUnavailable);
  };
  return {
      {name + ":avail", m.available ? "AVAILABLE" : std::string(kUnavailable)},
      {name + ":execution", or_unavailable(m.execution)},
      {name + ":program", or_unavailable(m.program)},
      {name + ":part_count", or_unavailable(std::to_string(m.part_count))},
      {name + ":line", or_unavailable(m.line >= 0 ? std::to_string(m.line) : "")},
      // A message carries a native code (none here) before its text.
      {name + ":message", "|" + or_unavailable(m.message)},
  };
}

std::vector<ShdrItem> MtconnectItems::update(const std::string& name, MachineItems next) {
  MachineItems& now = machines_[name];
  const auto before = render(name, now);
  now = std::move(next);
  auto after = render(name, now);
  std::vector<ShdrItem> changed;
  for (std::size_t i = 0; i < after.size(); ++i) {
    if (after[i].value != before[i].value) changed.push_back(std::move(after[i]));
  }
  return changed;
}

// A machine an admin added: offline until its port opens (a name is never
// reused, so it has no parts yet). A machine retired: every item
// UNAVAILABLE, and out of the list an agent gets on connect.
std::vector<ShdrItem> MtconnectItems::roster(std::string_view type, const std::string& name) {
  const bool known = machines_.contains(name);
  if (type == "machine.added") {
    if (known) return {};
    machines_[name] = MachineItems{};
    return render(name, machines_[name]);
  }
  if (!known) return {};
  machines_.erase(name);
  return render(name, MachineItems{});
}

std::vector<ShdrItem> MtconnectItems::apply(std::string_view type, const nlohmann::json& event) {
  const std::string name = text_of(event, "machine");
  if (type == "machine.added" || type == "machine.retired") return roster(type, name);
  const auto it = machines_.find(name);
  if (it == machines_.end()) return {};
  MachineItems m = it->second;
  if (type == "machine.state") {
    m.available = text_of(event, "state") != "offline";
  } else if (type == "machine.link_error") {
    m.message = text_of(event, "error");
  } else if (type == "machine.part") {
    m.part_count = event.value("part_count", m.part_count);
    if (event.contains("program") && event["program"].is_string()) m.program = event["program"];
  } else if (type == "machine.message") {
    m.message = text_of(event, "text");
  } else if (type.starts_with("job.")) {
    apply_job(type, event, m);
  }
  return update(name, std::move(m));
}

std::vector<ShdrItem> MtconnectItems::all() const {
  std::vector<ShdrItem> out;
  for (const auto& [name, m] : machines_) {
    auto items = render(name, m);
    out.insert(out.end(), items.begin(), items.end());
  }
  return out;
}

}  // namespace usina::dnc
