// What the controls said about their parts, kept in the store (schema
// version 3) so a restart of the server keeps it: each part line the control
// printed (DPRNT, a machine's pattern) is a row with its time, the cycle's
// time when known, the control's own count, and the program the machine was
// last given (for tool life). The machine's last `(MSG` text is kept too.
// The drip feeds' parts are the jobs' own (store_jobs.hpp).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "dnc/store.hpp"

namespace usina::dnc {

struct ControlPart {
  std::string machine;
  std::int64_t at_us = 0;
  std::optional<std::int64_t> cycle_us;       // the control's figure, or between two part lines
  std::optional<std::int64_t> control_count;  // the count the control printed
  std::string program;                        // the machine's last program ("" none)
  std::string revision;
};

// A part line, as one write (its program: the machine's last job done).
StoreResult<void> record_control_part(Store& store, ControlPart part);
// A cycle line printed after its part line: the machine's last part's cycle.
StoreResult<void> set_last_control_cycle(Store& store, std::string_view machine,
                                         std::int64_t cycle_us);
StoreResult<void> record_control_message(Store& store, std::string_view machine,
                                         std::string_view text, std::int64_t at_us);

// What the server shows of a machine's control after a restart.
struct ControlTotals {
  std::int64_t parts = 0;
  std::optional<std::int64_t> control_count;  // the last one printed
  std::optional<std::int64_t> last_cycle_us;  // the last part's
  std::int64_t last_part_at_us = 0;
  std::string last_message;
};

StoreResult<ControlTotals> control_totals(Store& store, std::string_view machine);
// The machine's control parts counted in [from_us, to_us), oldest first.
StoreResult<std::vector<ControlPart>> control_parts(Store& store, std::string_view machine,
                                                    std::int64_t from_us, std::int64_t to_us);

}  // namespace usina::dnc
