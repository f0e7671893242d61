#include "dnc/shift_calendar.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <chrono>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <iterator>
#include <map>
#include <mutex>
#include <span>

#include <fmt/format.h>

#include "sim/profile_keys.hpp"

namespace usina::dnc {
namespace {

namespace chr = std::chrono;

constexpr int kDayMinutes = 1440;
constexpr std::int64_t kDaySeconds = 86'400;
constexpr std::size_t kMaxShifts = 64;
constexpr std::size_t kMaxHolidays = 3660;  // ten years of days
constexpr std::array<std::string_view, 7> kDayNames{"mon", "tue", "wed", "thu",
                                                    "fri", "sat", "sun"};
constexpr std::array<std::string_view, 3> kCalendarKeys{"timezone", "shifts", "holidays"};
constexpr std::array<std::string_view, 3> kShiftKeys{"days", "start", "end"};

class Reader {
 public:
  Reader(std::string_view where, std::uint32_t file, core::DiagnosticSink& diags)
      : where_(where), file_(file), diags_(diags) {}

  void fail(const toml::source_region& at, std::string message) {
    report(core::Code::DncConfig, core::Severity::Error, at, std::move(message));
    ok = false;
  }

  void unknown(const toml::table& t, std::span<const std::string_view> keys, std::string_view in) {
    for (auto&& [key, node] : t) {
      (void)node;
      if (std::find(keys.begin(), keys.end(), key.str()) != keys.end()) continue;
      const std::string_view near = sim::nearest_key(key.str(), keys);
      report(core::Code::UnknownDncKey, core::Severity::Warning, key.source(),
             fmt::format("unknown key `{}` in {} is not read; {}", key.str(), in,
                         near.empty() ? std::string("docs/dnc.md lists the keys")
                                      : fmt::format("did you mean `{}`?", near)));
    }
  }

  const std::string& where() const { return where_; }

  bool ok = true;

 private:
  void report(core::Code code, core::Severity severity, const toml::source_region& at,
              std::string message) {
    core::Diagnostic d;
    d.code = code;
    d.severity = severity;
    d.loc.file = file_;
    d.loc.line = at.begin.line;
    d.loc.col = at.begin.column;
    d.message = std::move(message);
    diags_.report(std::move(d));
  }

  std::string where_;
  std::uint32_t file_;
  core::DiagnosticSink& diags_;
};

std::optional<int> day_index(std::string_view name) {
  for (std::size_t i = 0; i < kDayNames.size(); ++i)
    if (kDayNames[i] == name) return static_cast<int>(i);
  return std::nullopt;
}

// "mon-fri", "sat", "mon,wed,fri", "fri-mon" (a range may wrap past Sunday).
std::optional<std::uint8_t> parse_days(std::string_view text) {
  std::uint8_t days = 0;
  while (!text.empty()) {
    const std::size_t comma = text.find(',');
    const std::string_view item = text.substr(0, comma);
    text = comma == std::string_view::npos ? std::string_view() : text.substr(comma + 1);
    if (comma != std::string_view::npos && text.empty()) return std::nullopt;  // "mon,"
    const std::size_t dash = item.find('-');
    const auto first = day_index(item.substr(0, dash));
    const auto last = dash == std::string_view::npos ? first : day_index(item.substr(dash + 1));
    if (!first || !last) return std::nullopt;
    for (int d = *first;; d = (d + 1) % 7) {
      days |= static_cast<std::uint8_t>(1u << d);
      if (d == *last) break;
    }
  }
  return days == 0 ? std::nullopt : std::optional(days);
}

// "HH:MM", 00:00 to 23:59 (24:00 too when `end`).
std::optional<int> parse_clock(std::string_view text, bool end) {
  if (text.size() != 5 || text[2] != ':') return std::nullopt;
  int h = -1;
  int m = -1;
  if (std::from_chars(text.data(), text.data() + 2, h).ptr != text.data() + 2 ||
      std::from_chars(text.data() + 3, text.data() + 5, m).ptr != text.data() + 5)
    return std::nullopt;
  if (h < 0 || m < 0 || m > 59) return std::nullopt;
  const int minute = h * 60 + m;
  if (minute < kDayMinutes || (end && minute == kDayMinutes)) return minute;
  return std::nullopt;
}

std::string clock_text(int minute) {
  return fmt::format("{:02}:{:02}", minute / 60, minute % 60);
}

std::optional<Shift> read_shift(Reader& r, const toml::node& node, std::size_t i) {
  const std::string name = fmt::format("{}.shifts[{}]", r.where(), i + 1);
  const toml::table* t = node.as_table();
  if (t == nullptr) {
    r.fail(node.source(), fmt::format("{} must be a table {{days = \"mon-fri\", start = "
                                      "\"06:00\", end = \"14:00\"}}",
                                      name));
    return std::nullopt;
  }
  r.unknown(*t, kShiftKeys, name);
  Shift s;
  bool good = true;
  const toml::node* days = t->get("days");
  const auto day_set = days != nullptr ? days->value<std::string>() : std::nullopt;
  if (const auto parsed = day_set ? parse_days(*day_set) : std::nullopt) {
    s.days = *parsed;
  } else {
    r.fail(days != nullptr ? days->source() : t->source(),
           fmt::format("{}.days must be days of the week as \"mon-fri\", \"sat\" or "
                       "\"mon,wed,fri\" (mon tue wed thu fri sat sun)",
                       name));
    good = false;
  }
  for (const auto& [key, into] :
       {std::pair{"start", &s.start_minute}, std::pair{"end", &s.end_minute}}) {
    const toml::node* n = t->get(key);
    const auto text = n != nullptr ? n->value<std::string>() : std::nullopt;
    if (const auto minute =
            text ? parse_clock(*text, std::string_view(key) == "end") : std::nullopt) {
      *into = *minute;
    } else {
      r.fail(n != nullptr ? n->source() : t->source(),
             fmt::format("{}.{} must be a time \"HH:MM\" from 00:00 to {}", name, key,
                         std::string_view(key) == "end" ? "24:00" : "23:59"));
      good = false;
    }
  }
  if (good && s.start_minute == s.end_minute % kDayMinutes) {
    r.fail(t->get("end")->source(),
           fmt::format("{} starts and ends at {}: a shift of no length (or of 24 h: write "
                       "two shifts)",
                       name, clock_text(s.start_minute)));
    good = false;
  }
  return good ? std::optional(s) : std::nullopt;
}

// The first overlap of two shifts in the week's minutes, as "mon 13:00", or nothing.
std::optional<std::string> overlap(const Shift& a, const Shift& b) {
  constexpr int kWeek = 7 * kDayMinutes;
  for (int da = 0; da < 7; ++da) {
    if ((a.days & (1u << da)) == 0) continue;
    for (int db = 0; db < 7; ++db) {
      if ((b.days & (1u << db)) == 0) continue;
      const int a0 = da * kDayMinutes + a.start_minute;
      const int b0 = db * kDayMinutes + b.start_minute;
      // Compare b's start with a's instance shifted by a week either way (wrap past Sunday).
      for (const int shift : {-kWeek, 0, kWeek}) {
        const int lo = std::max(a0 + shift, b0);
        const int hi = std::min(a0 + shift + a.minutes(), b0 + b.minutes());
        if (lo < hi) {
          const int at = ((lo % kWeek) + kWeek) % kWeek;
          return fmt::format("{} {}", kDayNames[static_cast<std::size_t>(at / kDayMinutes)],
                             clock_text(at % kDayMinutes));
        }
      }
    }
  }
  return std::nullopt;
}

void read_shifts(Reader& r, const toml::node& node, ShiftCalendar& c) {
  const toml::array* list = node.as_array();
  if (list == nullptr || list->empty() || list->size() > kMaxShifts) {
    r.fail(node.source(),
           fmt::format("{}.shifts must be a list of 1 to {} shifts such as "
                       "[{{days = \"mon-fri\", start = \"06:00\", end = \"14:00\"}}]",
                       r.where(), kMaxShifts));
    return;
  }
  for (std::size_t i = 0; i < list->size(); ++i) {
    auto s = read_shift(r, *list->get(i), i);
    if (!s) continue;
    for (std::size_t j = 0; j < c.shifts.size(); ++j) {
      if (auto at = overlap(c.shifts[j], *s)) {
        r.fail(list->get(i)->source(),
               fmt::format("{}.shifts[{}] overlaps {}.shifts[{}] on {}: a minute belongs to one "
                           "shift at most",
                           r.where(), i + 1, r.where(), j + 1, *at));
      }
    }
    c.shifts.push_back(*s);
  }
}

void read_holidays(Reader& r, const toml::node& node, ShiftCalendar& c) {
  const toml::array* list = node.as_array();
  if (list == nullptr || list->size() > kMaxHolidays) {
    r.fail(node.source(), fmt::format("{}.holidays must be a list of at most {} dates "
                                      "\"YYYY-MM-DD\"",
                                      r.where(), kMaxHolidays));
    return;
  }
  for (std::size_t i = 0; i < list->size(); ++i) {
    const toml::node& n = *list->get(i);
    const auto text = n.value<std::string>();
    const auto day = text ? day_number(*text) : std::nullopt;
    if (!day) {
      r.fail(n.source(),
             fmt::format("{}.holidays[{}] must be a date \"YYYY-MM-DD\"", r.where(), i + 1));
      continue;
    }
    c.holidays.insert(*day);
  }
}

// The process's time zone is the C library's global state: reading another
// zone sets TZ and puts it back, one thread at a time. Only zone_offsets
// does it, while the configuration is read.
class ZoneScope {
 public:
  explicit ZoneScope(const std::string& zone) : lock_(mutex()) {
    if (const char* tz = std::getenv("TZ")) saved_ = tz;
    ::setenv("TZ", (":" + zone).c_str(), 1);
    ::tzset();
  }

  ~ZoneScope() {
    if (saved_) {
      ::setenv("TZ", saved_->c_str(), 1);
    } else {
      ::unsetenv("TZ");
    }
    ::tzset();
  }

  ZoneScope(const ZoneScope&) = delete;
  ZoneScope& operator=(const ZoneScope&) = delete;

  // The zone's offset from UTC, in seconds, at `utc_s`.
  static std::int32_t offset_at(std::int64_t utc_s) {
    const auto t = static_cast<std::time_t>(utc_s);
    std::tm tm{};
    ::localtime_r(&t, &tm);
    return static_cast<std::int32_t>(tm.tm_gmtoff);
  }

  static std::mutex& mutex() {
    static std::mutex m;
    return m;
  }

 private:
  std::unique_lock<std::mutex> lock_;
  std::optional<std::string> saved_;
};

constexpr std::int64_t kProbeFrom = 0;            // 1970-01-01 UTC
constexpr std::int64_t kProbeTo = 4'133'980'800;  // 2101-01-01 UTC
// A day: in tzdata 2025b no zone's changes are closer than 7 days
// (America/Boa_Vista, 601,200 s), and the daily table of each of its 645
// zones is the hourly one (ZoneOffsets.EveryZoneDailyIsHourly, run by hand).
constexpr std::int64_t kProbeStep = 86'400;

// The zone's offsets by asking glibc every `step` seconds of 1970 to 2100,
// and to the second (bisecting) in each step the offset changes in. Asking
// glibc rather than reading the TZif file ourselves keeps its reading of
// the file's POSIX rule for the years past the file's last transition, and
// its answers to the second.
ZoneOffsets probe_offsets(std::int64_t step) {
  ZoneOffsets z;
  z.initial_s = ZoneScope::offset_at(kProbeFrom);
  std::int32_t current = z.initial_s;
  for (std::int64_t t = kProbeFrom + step; t < kProbeTo + step; t += step) {
    const std::int64_t at = std::min(t, kProbeTo);
    const std::int32_t now = ZoneScope::offset_at(at);
    if (now == current) continue;
    std::int64_t lo = t - step;  // still `current`
    std::int64_t hi = at;        // already changed
    while (hi - lo > 1) {
      const std::int64_t mid = lo + (hi - lo) / 2;
      (ZoneScope::offset_at(mid) == current ? lo : hi) = mid;
    }
    z.changes.push_back({hi, ZoneScope::offset_at(hi)});
    current = z.changes.back().offset_s;
    if (current != now) t = hi;  // a second change within the step: go on from this one
  }
  return z;
}

// a / b rounded down (to the day or second before 1970 too).
std::int64_t floor_div(std::int64_t a, std::int64_t b) {
  return a >= 0 ? a / b : (a - b + 1) / b;
}

// The UTC instant of the wall-clock time `local_s` (seconds since 1970 as
// if the wall clock were UTC): the first of two when the clocks go back;
// on the old offset when the clocks skip it.
std::int64_t utc_of(const ZoneOffsets* zone, std::int64_t local_s) {
  const auto offset = [zone](std::int64_t t) -> std::int64_t {
    return zone != nullptr ? zone->offset_at(t) : 0;
  };
  const std::int64_t before = offset(local_s - kDaySeconds);
  const std::int64_t after = offset(local_s + kDaySeconds);
  const std::int64_t early = local_s - std::max(before, after);
  const std::int64_t late = local_s - std::min(before, after);
  for (const std::int64_t t : {early, late})
    if (t + offset(t) == local_s) return t;
  return local_s - before;
}

}  // namespace

std::int64_t ZoneOffsets::offset_at(std::int64_t utc_s) const {
  const auto after = std::upper_bound(changes.begin(), changes.end(), utc_s,
                                      [](std::int64_t t, const Change& c) { return t < c.at_s; });
  return after == changes.begin() ? initial_s : std::prev(after)->offset_s;
}

std::shared_ptr<const ZoneOffsets> zone_offsets(const std::string& name) {
  static std::map<std::string, std::shared_ptr<const ZoneOffsets>> read;
  {
    const std::lock_guard lock(ZoneScope::mutex());
    if (auto it = read.find(name); it != read.end()) return it->second;
  }
  auto zone = std::make_shared<const ZoneOffsets>(probe_zone_offsets(name, kProbeStep));
  const std::lock_guard lock(ZoneScope::mutex());
  return read.emplace(name, std::move(zone)).first->second;
}

ZoneOffsets probe_zone_offsets(const std::string& name, std::int64_t step_s) {
  const ZoneScope zone(name);
  return probe_offsets(std::max<std::int64_t>(step_s, 1));
}

int Shift::minutes() const {
  return end_minute > start_minute ? end_minute - start_minute
                                   : end_minute + kDayMinutes - start_minute;
}

std::string timezone_error(std::string_view name) {
  if (name.empty() || name.size() > 64) return "a zone's name has 1 to 64 characters";
  for (const char ch : name) {
    const bool good = (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') ||
                      (ch >= '0' && ch <= '9') || ch == '_' || ch == '+' || ch == '-' || ch == '/';
    if (!good) return fmt::format("`{}` holds a character no zone's name has", name);
  }
  if (name.front() == '/' || name.front() == '-' || name.find("//") != std::string_view::npos)
    return fmt::format("`{}` is a path, not a zone's name such as \"Europe/Berlin\"", name);
  std::ifstream in("/usr/share/zoneinfo/" + std::string(name), std::ios::binary);
  std::array<char, 4> magic{};
  if (!in.read(magic.data(), magic.size()) || std::string_view(magic.data(), 4) != "TZif") {
    return fmt::format(
        "no zone `{}` in /usr/share/zoneinfo (Debian's tzdata): give a name "
        "such as \"America/Sao_Paulo\" or \"UTC\"",
        name);
  }
  return {};
}

std::optional<ShiftCalendar> read_calendar(const toml::table& table, std::string_view where,
                                           std::uint32_t file_id, core::DiagnosticSink& diags) {
  Reader r(where, file_id, diags);
  r.unknown(table, kCalendarKeys, fmt::format("[{}]", where));
  ShiftCalendar c;
  const toml::node* zone = table.get("timezone");
  const auto name = zone != nullptr ? zone->value<std::string>() : std::nullopt;
  if (!name) {
    r.fail(zone != nullptr ? zone->source() : table.source(),
           fmt::format("{}.timezone must be a zone's name such as \"America/Sao_Paulo\" (the "
                       "shifts' clock)",
                       where));
  } else if (std::string why = timezone_error(*name); !why.empty()) {
    r.fail(zone->source(), fmt::format("{}.timezone: {}", where, why));
  } else {
    c.timezone = *name;
    c.offsets = zone_offsets(c.timezone);
  }
  if (const toml::node* shifts = table.get("shifts")) {
    read_shifts(r, *shifts, c);
  } else {
    r.fail(table.source(), fmt::format("{}.shifts must be given: a list of shifts", where));
  }
  if (const toml::node* holidays = table.get("holidays")) read_holidays(r, *holidays, c);
  return r.ok ? std::optional(std::move(c)) : std::nullopt;
}

std::vector<std::pair<std::int64_t, std::int64_t>> shift_times(const ShiftCalendar& calendar,
                                                               std::int64_t from_us,
                                                               std::int64_t to_us) {
  std::vector<std::pair<std::int64_t, std::int64_t>> out;
  if (to_us <= from_us || calendar.shifts.empty()) return out;
  const auto floor_day = [](std::int64_t us) {
    return floor_div(floor_div(us, 1'000'000), kDaySeconds);
  };
  // A zone is within a day of UTC and a shift lasts a day at most: the
  // local dates from two days before to a day after cover every shift.
  const std::int64_t first = floor_day(from_us) - 2;
  const std::int64_t last = floor_day(to_us - 1) + 1;
  // The table built when the calendar was read: no TZ, no libc zone call
  // here, so a server's threads never see the environment change.
  const ZoneOffsets* zone = calendar.offsets.get();
  for (std::int64_t date = first; date <= last; ++date) {
    if (calendar.holidays.contains(date)) continue;
    // 1970-01-01 was a Thursday (3 counting from Monday).
    const int weekday = static_cast<int>(((date % 7) + 7 + 3) % 7);
    for (const Shift& s : calendar.shifts) {
      if ((s.days & (1u << weekday)) == 0) continue;
      const std::int64_t local = date * kDaySeconds + s.start_minute * 60;
      const std::int64_t start = utc_of(zone, local) * 1'000'000;
      const std::int64_t end = utc_of(zone, local + s.minutes() * 60) * 1'000'000;
      if (end > from_us && start < to_us) out.emplace_back(start, end);
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<CalendarDay> calendar_days(const ZoneOffsets* zone, std::int64_t first,
                                       std::int64_t last) {
  std::vector<CalendarDay> out;
  if (last < first) return out;
  out.reserve(static_cast<std::size_t>(last - first + 1));
  std::int64_t start = utc_of(zone, first * kDaySeconds);
  for (std::int64_t date = first; date <= last; ++date) {
    const std::int64_t end = utc_of(zone, (date + 1) * kDaySeconds);
    out.push_back({date, start * 1'000'000, end * 1'000'000});
    start = end;
  }
  return out;
}

std::int64_t calendar_date(const ZoneOffsets* zone, std::int64_t utc_us) {
  const std::int64_t s = floor_div(utc_us, 1'000'000);
  return floor_div(s + (zone != nullptr ? zone->offset_at(s) : 0), kDaySeconds);
}

std::optional<std::int64_t> day_number(std::string_view text) {
  if (text.size() != 10 || text[4] != '-' || text[7] != '-') return std::nullopt;
  int y = 0;
  unsigned m = 0;
  unsigned d = 0;
  const auto read = [](std::string_view s, auto& v) {
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    return ec == std::errc() && end == s.data() + s.size();
  };
  if (!read(text.substr(0, 4), y) || !read(text.substr(5, 2), m) || !read(text.substr(8, 2), d))
    return std::nullopt;
  const chr::year_month_day date{chr::year{y}, chr::month{m}, chr::day{d}};
  if (!date.ok()) return std::nullopt;
  return chr::sys_days(date).time_since_epoch().count();
}

}  // namespace usina::dnc
