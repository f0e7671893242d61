// Utilisation per day and tool-life counts, from what the store keeps: each
// machine's activity changes (schema version 4: feeding, transfer, idle,
// alarm, down, off), its jobs, and the parts its control printed
// (store_parts.hpp). Days are UTC calendar days of 24 h, or the days of a
// calendar's zone (shift_calendar.hpp's calendar_days: 23 h or 25 h on the
// days its clocks change).
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "dnc/shift_calendar.hpp"
#include "dnc/store.hpp"
#include "dnc/store_tool_resets.hpp"

namespace usina::dnc {

// What a machine is doing, as the server sees it through its link.
//   feeding   a drip feed is running (the machine cuts as the program arrives)
//   transfer  a whole program is sent or received
//   idle      the link is up and nothing moves on it
//   alarm     a job ended on an alarm (no XON); until the next job starts
//   down      the link is down (the port did not open, the device server is away)
//   off       the server was stopped
constexpr std::string_view kActivities[] = {"feeding", "transfer", "idle", "alarm", "down", "off"};

StoreResult<void> record_activity(Store& store, std::string_view machine, std::string_view activity,
                                  std::int64_t at_us);

// The server is alive at `at_us` (schema version 5): written every few
// seconds while it runs (server_machines.cpp).
StoreResult<void> record_heartbeat(Store& store, std::int64_t at_us);

// The server's last sign of life: its last heartbeat, or nothing before the first.
StoreResult<std::optional<std::int64_t>> last_heartbeat(Store& store);

// At a start: a machine whose last activity is not "off" belonged to a
// server that died without stopping (kill -9, a power cut). Its activity
// ends with "off" at the later of that activity's start and the last
// heartbeat, so the time the server was dead is not counted as what the
// machine was last seen doing (at most one heartbeat's interval is).
// Returns how many machines it closed.
StoreResult<std::int64_t> close_activity_of_dead_server(Store& store);

struct MachineDay {
  std::int64_t day = 0;       // the date, days since 1970-01-01
  std::int64_t start_us = 0;  // its midnight (UTC microseconds)
  std::int64_t end_us = 0;    // the next day's

  double length_seconds() const { return static_cast<double>(end_us - start_us) / 1e6; }

  std::map<std::string, double> seconds;  // activity → seconds of the day
  double control_cycle_seconds = 0.0;     // cycles the control printed (ran from its memory)
  std::int64_t parts = 0;                 // drip feeds done + the control's part lines
  double known_seconds = 0.0;             // the day's seconds with a record, up to now
  // With shifts (machine_days' `shifts`): their planned seconds in the day,
  // and the running seconds (feeding, the control's cycles) inside them.
  double scheduled_seconds = 0.0;
  double running_in_shift_seconds = 0.0;
};

// [start, end) in microseconds since 1970 (UTC), in order, not overlapping.
using TimeSpans = std::vector<std::pair<std::int64_t, std::int64_t>>;

// The `days` of `machine` (consecutive: each starts where the one before
// ends). With `shifts` (shift_calendar.hpp's shift_times), each day's
// scheduled and in-shift running seconds too; a control's cycle runs from
// its part line back by the cycle's seconds (within the day).
StoreResult<std::vector<MachineDay>> machine_days(Store& store, std::string_view machine,
                                                  const std::vector<CalendarDay>& days,
                                                  const TimeSpans* shifts = nullptr);

// UTC days `first_day` to `last_day` (inclusive).
StoreResult<std::vector<MachineDay>> machine_days(Store& store, std::string_view machine,
                                                  std::int64_t first_day, std::int64_t last_day,
                                                  const TimeSpans* shifts = nullptr);

// A tool's use on a machine: each part made counts once for each tool its
// program uses, with that tool's cutting time from the revision's check.
struct ToolUse {
  int tool = 0;
  std::int64_t parts = 0;
  double cutting_seconds = 0.0;
  double seconds = 0.0;            // cutting, rapid and the rest while the tool is in the spindle
  std::optional<ToolReset> reset;  // its last reset up to the range's end (store_tool_resets.hpp)
  bool from_reset = false;         // its parts are counted from that reset, not the range's start
};

struct ToolLife {
  std::vector<ToolUse> tools;              // by tool number
  std::int64_t parts = 0;                  // parts counted in the range
  std::int64_t parts_without_program = 0;  // control parts before any job was done
  std::int64_t parts_without_tools = 0;    // revisions checked before tool lists were kept
};

// The parts made in [from_us, to_us). With `from_resets`, a tool reset in
// that range counts only the parts made at or after its last reset (a tool
// reset but not used since is listed with no parts).
StoreResult<ToolLife> tool_life(Store& store, std::string_view machine, std::int64_t from_us,
                                std::int64_t to_us, bool from_resets = false);

}  // namespace usina::dnc
