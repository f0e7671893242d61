// A shift calendar (usina-serve.toml's `[calendar]`, or a machine's own
// `calendar` table): weekly shifts in a named time zone, and holidays on
// which no shift starts. The utilisation per day (api_utilisation.cpp)
// measures running time against the planned time of these shifts.
//
//   [calendar]
//   timezone = "America/Sao_Paulo"     # a zone of /usr/share/zoneinfo
//   shifts = [{days = "mon-fri", start = "06:00", end = "14:00"},
//             {days = "mon-fri", start = "22:00", end = "06:00"}]  # ends the next day
//   holidays = ["2026-12-25"]
//
// Times are the zone's wall-clock times: a shift on a day the clocks change
// is as long as the clocks say (22:00 to 06:00 is 7 h in Berlin on
// 2026-03-29, 9 h on 2026-10-25). A start or end that the change skips
// (02:30 on the spring-forward night) is the instant it would have been on
// the old offset (03:30 summer time); one that happens twice is the first.
//
// The zone is read once, when the calendar is read (before the server starts
// a thread): glibc gives its offsets through TZ, and changing the
// environment while other threads may call getenv is undefined behaviour.
// Every later conversion uses the table of offset changes built then.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <toml++/toml.h>

#include "core/diagnostic.hpp"

namespace usina::dnc {

struct Shift {
  std::uint8_t days = 0;  // the weekdays it starts on: bit 0 Monday ... bit 6 Sunday
  int start_minute = 0;   // of the day, 0 to 1439
  int end_minute = 0;     // 1 to 1440; at or before start: the next day
  int minutes() const;    // its length on the clock, 1 to 1440
};

// A zone's offsets from UTC from 1970 to 2100, as glibc gives them: the
// offset before the first change, then each change to the second. Before
// 1970 the first offset holds, after 2100 the last.
struct ZoneOffsets {
  struct Change {
    std::int64_t at_s = 0;  // UTC seconds since 1970 from which `offset_s` holds
    std::int32_t offset_s = 0;
    bool operator==(const Change&) const = default;
  };

  std::int32_t initial_s = 0;   // before the first change
  std::vector<Change> changes;  // in order of time
  std::int64_t offset_at(std::int64_t utc_s) const;
  bool operator==(const ZoneOffsets&) const = default;
};

// The offsets of the zone `name` (a name timezone_error accepts). It sets TZ
// for a moment, one call at a time, and puts it back: call it only while no
// other thread runs (the configuration is read before the server starts).
// A zone read before is not read again.
std::shared_ptr<const ZoneOffsets> zone_offsets(const std::string& name);

// The table as zone_offsets builds it, glibc asked every `step_s` seconds
// and each change bisected to the second: zone_offsets asks daily. Two
// changes within a step that come back to the first offset would be
// missed; a test compares the daily table with an hourly one for every
// zone of /usr/share/zoneinfo. The same TZ rules as zone_offsets.
ZoneOffsets probe_zone_offsets(const std::string& name, std::int64_t step_s);

struct ShiftCalendar {
  std::string timezone;  // a name under /usr/share/zoneinfo ("UTC", "Europe/Berlin")
  std::shared_ptr<const ZoneOffsets> offsets;  // its offsets (none: UTC)
  std::vector<Shift> shifts;                   // none overlap (read_calendar refuses it)
  std::set<std::int64_t> holidays;             // local dates, days since 1970-01-01
  std::string source;                          // "server" ([calendar]) or "machine" (its own)
};

// The calendar of `table` (its keys `timezone`, `shifts`, `holidays`), or
// nothing with an E_DNC_CONFIG diagnostic at the bad key. `where` names the
// table in messages: "calendar", "machine `m1` calendar". An unknown key is
// the warning W_UNKNOWN_DNC_KEY.
std::optional<ShiftCalendar> read_calendar(const toml::table& table, std::string_view where,
                                           std::uint32_t file_id, core::DiagnosticSink& diags);

// Why `name` is no zone this machine knows (empty when it is one): a name is
// letters, digits and `_ + - /`, never a path out of /usr/share/zoneinfo,
// and names a TZif file there.
std::string timezone_error(std::string_view name);

// The shifts that overlap [from_us, to_us) (UTC microseconds since 1970),
// as [start, end) in UTC microseconds, in order.
std::vector<std::pair<std::int64_t, std::int64_t>> shift_times(const ShiftCalendar& calendar,
                                                               std::int64_t from_us,
                                                               std::int64_t to_us);

// A calendar day as UTC instants: from its midnight to the next day's.
struct CalendarDay {
  std::int64_t date = 0;      // days since 1970-01-01
  std::int64_t start_us = 0;  // UTC microseconds since 1970
  std::int64_t end_us = 0;    // the next day's start
};

// The dates `first` to `last` (both included) as days of `zone`: each from
// its local midnight to the next, so 23 h or 25 h on the days the clocks
// change (a midnight that a change skips is taken on the old offset, as a
// shift's start is). Without a zone (nullptr): UTC days of 24 h.
std::vector<CalendarDay> calendar_days(const ZoneOffsets* zone, std::int64_t first,
                                       std::int64_t last);

// The date in `zone` (nullptr: UTC) at the UTC instant `utc_us`.
std::int64_t calendar_date(const ZoneOffsets* zone, std::int64_t utc_us);

// Days since 1970-01-01 of "YYYY-MM-DD"; nothing when it is not a date.
std::optional<std::int64_t> day_number(std::string_view text);

}  // namespace usina::dnc
