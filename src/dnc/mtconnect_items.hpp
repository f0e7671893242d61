// What the MTConnect adapter says of each machine: its data items (SHDR
// keys `MACHINE:avail`, `:execution`, `:program`, `:part_count`, `:line`,
// `:message`), kept from the server's events. A machine whose link is lost
// has every item UNAVAILABLE, as an agent expects; its last values come
// back with the link. A machine added or retired while the server runs is
// in or out of the list at once (`machine.added`, `machine.retired`).
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace usina::dnc {

struct MachineItems {
  bool available = false;
  std::string execution = "READY";  // READY, ACTIVE, INTERRUPTED, STOPPED
  std::string program;
  std::int64_t part_count = 0;
  std::int64_t line = -1;  // the last line the drip feed sent; -1: none yet
  std::string message;     // the last message (a (MSG line, why a job ended)
};

// One SHDR key and its value(s) ("key|value", a message "key|code|text").
struct ShdrItem {
  std::string key;
  std::string value;
};

class MtconnectItems {
 public:
  void add_machine(const std::string& name, const MachineItems& start);
  // Folds a server event in; the items whose value changed.
  std::vector<ShdrItem> apply(std::string_view type, const nlohmann::json& event);
  // Every item of every machine, as they stand.
  std::vector<ShdrItem> all() const;

 private:
  std::vector<ShdrItem> render(const std::string& name, const MachineItems& m) const;
  std::vector<ShdrItem> update(const std::string& name, MachineItems next);
  std::vector<ShdrItem> roster(std::string_view type, const std::string& name);

  std::map<std::string, MachineItems> machines_;
};

// `value` as SHDR carries it: no line ends; a value with `|` quoted, the
// pipe escaped.
std::string shdr_value(std::string_view value);
// An SHDR timestamp of the system clock: 2026-12-01T22:40:00.123Z.
std::string shdr_timestamp();

}  // namespace usina::dnc
