// Shift calendars for utilisation: [calendar] and a machine's own table read
// and every bad key refused at its line; shifts across midnight, the DST
// change days of Europe/Berlin, holidays; the scheduled and in-shift seconds
// per UTC day from the store (both back ends), and the utilisation route of a
// server whose machine has a calendar.
#include "dnc/shift_calendar.hpp"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <limits>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "api_control.hpp"
#include "dnc/server_config.hpp"
#include "dnc/store_parts.hpp"
#include "dnc/store_utilisation.hpp"
#include "store_fixture.hpp"

namespace usina::dnc {
namespace {

constexpr std::int64_t kHourUs = 3'600'000'000;
constexpr std::int64_t kDayUs = 24 * kHourUs;

// Days since 1970 of a date.
std::int64_t date_of(int y, unsigned m, unsigned d) {
  using namespace std::chrono;
  return sys_days(year_month_day{year{y}, month{m}, day{d}}).time_since_epoch().count();
}

std::optional<ShiftCalendar> calendar(const std::string& toml, core::DiagnosticList& diags) {
  auto c = read_server_config(toml, 0, diags);
  return c ? c->calendar : std::nullopt;
}

ShiftCalendar good(const std::string& body) {
  core::DiagnosticList diags;
  auto c = calendar("[calendar]\n" + body, diags);
  EXPECT_TRUE(c) << body << (diags.all().empty() ? "" : diags.all()[0].message);
  return c.value_or(ShiftCalendar{});
}

// Hours of [from, to) inside the calendar's shifts.
double hours(const ShiftCalendar& c, std::int64_t from_us, std::int64_t to_us) {
  std::int64_t total = 0;
  for (const auto& [a, b] : shift_times(c, from_us, to_us))
    total += std::min(b, to_us) - std::max(a, from_us);
  return static_cast<double>(total) / static_cast<double>(kHourUs);
}

double day_hours(const ShiftCalendar& c, std::int64_t d) {
  return hours(c, d * kDayUs, (d + 1) * kDayUs);
}

struct BadKey {
  const char* body;  // after "[calendar]\n" (line 1): the bad key is on line 2 or 3
  unsigned line;
  const char* says;
};

TEST(ShiftCalendarConfig, EachBadKeyIsAnErrorAtItsLine) {
  const std::string shift = "shifts = [{days = \"mon-fri\", start = \"06:00\", end = \"14:00\"}]\n";
  const BadKey cases[] = {
      {"timezone = \"Mars/Olympus\"\n", 2, "no zone `Mars/Olympus` in /usr/share/zoneinfo"},
      {"timezone = \"../../etc/passwd\"\n", 2, "holds a character no zone's name has"},
      {"timezone = \"/etc/localtime\"\n", 2, "is a path"},
      {"timezone = 5\n", 2, "calendar.timezone must be a zone's name"},
      {"timezone = \"UTC\"\nshifts = []\n", 3, "calendar.shifts must be a list of 1 to 64"},
      {"timezone = \"UTC\"\nshifts = \"mon-fri\"\n", 3, "calendar.shifts must be a list"},
      {"timezone = \"UTC\"\nshifts = [5]\n", 3, "calendar.shifts[1] must be a table"},
      {"timezone = \"UTC\"\nshifts = [{days = \"mon-fry\", start = \"06:00\", end = \"14:00\"}]\n",
       3, "calendar.shifts[1].days must be days of the week"},
      {"timezone = \"UTC\"\nshifts = [{days = \"mon,\", start = \"06:00\", end = \"14:00\"}]\n", 3,
       "shifts[1].days"},
      {"timezone = \"UTC\"\nshifts = [{start = \"06:00\", end = \"14:00\"}]\n", 3,
       "shifts[1].days"},
      {"timezone = \"UTC\"\nshifts = [{days = \"sat\", start = \"6:00\", end = \"14:00\"}]\n", 3,
       "calendar.shifts[1].start must be a time \"HH:MM\" from 00:00 to 23:59"},
      {"timezone = \"UTC\"\nshifts = [{days = \"sat\", start = \"24:00\", end = \"06:00\"}]\n", 3,
       "shifts[1].start"},
      {"timezone = \"UTC\"\nshifts = [{days = \"sat\", start = \"06:00\", end = \"14:60\"}]\n", 3,
       "calendar.shifts[1].end must be a time \"HH:MM\" from 00:00 to 24:00"},
      {"timezone = \"UTC\"\nshifts = [{days = \"sat\", start = \"06:00\", end = \"06:00\"}]\n", 3,
       "starts and ends at 06:00: a shift of no length"},
      {"timezone = \"UTC\"\nholidays = [\"2026-12-25\"]\n", 1, "calendar.shifts must be given"},
      {"timezone = \"UTC\"\nholidays = [\"2026-02-30\"]\nshifts = []\n", 3,
       "calendar.holidays[1] must be a date \"YYYY-MM-DD\""},
      {"timezone = \"UTC\"\nholidays = \"2026-12-25\"\n", 3, "calendar.holidays must be a list"},
      {"timezone = \"UTC\"\nshifts = [{days = \"mon-fri\", start = \"06:00\", end = \"14:00\"},\n"
       "  {days = \"mon-fri\", start = \"13:00\", end = \"22:00\"}]\n",
       4, "calendar.shifts[2] overlaps calendar.shifts[1] on mon 13:00"},
      // Across midnight: Friday's night shift runs into Saturday's morning.
      {"timezone = \"UTC\"\nshifts = [{days = \"fri\", start = \"22:00\", end = \"06:00\"},\n"
       "  {days = \"sat\", start = \"05:00\", end = \"13:00\"}]\n",
       4, "overlaps calendar.shifts[1] on sat 05:00"},
      // Past the week's end: Sunday's night shift runs into Monday's morning.
      {"timezone = \"UTC\"\nshifts = [{days = \"mon\", start = \"05:00\", end = \"13:00\"},\n"
       "  {days = \"sun\", start = \"22:00\", end = \"06:00\"}]\n",
       4, "overlaps calendar.shifts[1] on mon 05:00"},
  };
  for (const BadKey& k : cases) {
    core::DiagnosticList diags;
    std::string text = std::string("[calendar]\n") + k.body;
    if (std::string_view(k.body).find("shifts") == std::string_view::npos &&
        std::string_view(k.body).find("holidays") == std::string_view::npos)
      text += shift;
    EXPECT_FALSE(read_server_config(text, 0, diags)) << k.body;
    bool found = false;
    for (const core::Diagnostic& d : diags.all()) {
      if (d.code != core::Code::DncConfig || d.message.find(k.says) == std::string::npos) continue;
      found = true;
      EXPECT_EQ(d.loc.line, k.line) << k.body << d.message;
    }
    EXPECT_TRUE(found) << k.body << " wanted: " << k.says
                       << "\ngot: " << (diags.all().empty() ? "nothing" : diags.all()[0].message);
  }
}

TEST(ShiftCalendarConfig, UnknownKeysAreWarningsAndTablesMustBeTables) {
  core::DiagnosticList diags;
  auto c = read_server_config(
      "[calendar]\ntimezone = \"UTC\"\nholiday = []\n"
      "shifts = [{days = \"sat\", start = \"06:00\", end = \"14:00\", break = \"10:00\"}]\n",
      0, diags);
  ASSERT_TRUE(c);
  ASSERT_EQ(diags.all().size(), 2u);
  std::string all;
  for (const core::Diagnostic& d : diags.all()) {
    EXPECT_EQ(d.code, core::Code::UnknownDncKey);
    all += d.message + "\n";
  }
  EXPECT_NE(all.find("`holiday` in [calendar] is not read; did you mean `holidays`?"),
            std::string::npos)
      << all;
  EXPECT_NE(all.find("`break` in calendar.shifts[1]"), std::string::npos) << all;
  for (const char* text :
       {"calendar = 5\n",
        "[[machine]]\nname = \"m1\"\nport = \"/dev/null\"\ncalendar = \"UTC\"\n"}) {
    core::DiagnosticList d2;
    EXPECT_FALSE(read_server_config(text, 0, d2)) << text;
    ASSERT_FALSE(d2.all().empty()) << text;
    EXPECT_NE(d2.all().back().message.find("calendar must be a table"), std::string::npos)
        << d2.all().back().message;
  }
}

TEST(ShiftCalendarConfig, AMachineTakesTheServersCalendarUnlessItHasItsOwn) {
  core::DiagnosticList diags;
  auto c = read_server_config(
      "[calendar]\ntimezone = \"America/Sao_Paulo\"\n"
      "shifts = [{days = \"mon-fri\", start = \"06:00\", end = \"14:00\"}]\n"
      "holidays = [\"2026-12-25\", \"2027-01-01\"]\n"
      "[[machine]]\nname = \"m1\"\nport = \"/dev/null\"\n"
      "[[machine]]\nname = \"m2\"\nport = \"/dev/null\"\n"
      "[machine.calendar]\ntimezone = \"Europe/Berlin\"\n"
      "shifts = [{days = \"mon-sat\", start = \"22:00\", end = \"06:00\"},\n"
      "          {days = \"mon-fri\", start = \"06:00\", end = \"14:00\"}]\n",
      0, diags);
  ASSERT_TRUE(c) << (diags.all().empty() ? "" : diags.all()[0].message);
  EXPECT_TRUE(diags.all().empty());
  ASSERT_EQ(c->machines.size(), 2u);
  ASSERT_TRUE(c->machines[0].calendar);
  EXPECT_EQ(c->machines[0].calendar->timezone, "America/Sao_Paulo");
  EXPECT_EQ(c->machines[0].calendar->source, "server");
  EXPECT_EQ(c->machines[0].calendar->holidays.size(), 2u);
  ASSERT_TRUE(c->machines[1].calendar);
  EXPECT_EQ(c->machines[1].calendar->timezone, "Europe/Berlin");
  EXPECT_EQ(c->machines[1].calendar->source, "machine");
  EXPECT_EQ(c->machines[1].calendar->shifts.size(), 2u);
  // Without [calendar], no machine has one.
  core::DiagnosticList none;
  auto plain = read_server_config("[[machine]]\nname = \"m1\"\nport = \"/dev/null\"\n", 0, none);
  ASSERT_TRUE(plain);
  EXPECT_FALSE(plain->machines[0].calendar);
}

TEST(ShiftTimes, AShiftAcrossMidnightCountsInBothUtcDays) {
  const ShiftCalendar c = good(
      "timezone = \"UTC\"\nshifts = [{days = \"mon-fri\", start = \"22:00\", end = \"06:00\"}]\n");
  // 2026-06-02 is a Tuesday: Monday's shift ends at 06:00, Tuesday's starts at 22:00.
  const std::int64_t tue = date_of(2026, 6, 2);
  EXPECT_DOUBLE_EQ(day_hours(c, tue), 8.0);
  const auto spans = shift_times(c, tue * kDayUs, (tue + 1) * kDayUs);
  ASSERT_EQ(spans.size(), 2u);
  EXPECT_EQ(spans[0].first, (tue - 1) * kDayUs + 22 * kHourUs);
  EXPECT_EQ(spans[0].second, tue * kDayUs + 6 * kHourUs);
  EXPECT_EQ(spans[1].second, (tue + 1) * kDayUs + 6 * kHourUs);
  // Monday only gets its own start; Saturday only Friday's end; Sunday nothing.
  EXPECT_DOUBLE_EQ(day_hours(c, tue - 1), 2.0);
  EXPECT_DOUBLE_EQ(day_hours(c, tue + 4), 6.0);
  EXPECT_DOUBLE_EQ(day_hours(c, tue + 5), 0.0);
}

TEST(ShiftTimes, TheClockChangesOfEuropeBerlinMakeShiftsShorterAndLonger) {
  const ShiftCalendar early = good(
      "timezone = \"Europe/Berlin\"\nshifts = [{days = \"mon-sun\", start = \"01:00\", end = "
      "\"04:00\"}]\n");
  // 2026-03-29: 02:00 CET becomes 03:00 CEST. 01:00 CET is 00:00 UTC, 04:00 CEST 02:00 UTC.
  const std::int64_t spring = date_of(2026, 3, 29);
  EXPECT_DOUBLE_EQ(day_hours(early, spring - 1), 3.0);
  // The UTC day holds that 2 h shift, and the first hour of the next, which
  // on summer time starts at 23:00 UTC.
  EXPECT_DOUBLE_EQ(day_hours(early, spring), 3.0);
  const auto s = shift_times(early, spring * kDayUs, (spring + 1) * kDayUs);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].first, spring * kDayUs);
  EXPECT_EQ(s[0].second, spring * kDayUs + 2 * kHourUs);
  EXPECT_EQ(s[1].first, spring * kDayUs + 23 * kHourUs);
  // 2026-10-25: 03:00 CEST becomes 02:00 CET; 01:00 CEST is 23:00 UTC the day before.
  const std::int64_t autumn = date_of(2026, 10, 25);
  EXPECT_DOUBLE_EQ(hours(early, autumn * kDayUs - kHourUs, (autumn + 1) * kDayUs - kHourUs), 4.0);

  const ShiftCalendar night = good(
      "timezone = \"Europe/Berlin\"\nshifts = [{days = \"sat\", start = \"22:00\", end = "
      "\"06:00\"}]\n");
  // Saturday 2026-03-28 22:00 CET to Sunday 06:00 CEST: 7 h; 2026-10-24 to the 25th: 9 h.
  EXPECT_DOUBLE_EQ(hours(night, (spring - 2) * kDayUs, (spring + 2) * kDayUs), 7.0);
  EXPECT_DOUBLE_EQ(hours(night, (autumn - 2) * kDayUs, (autumn + 2) * kDayUs), 9.0);

  // A start the change skips (02:30) is taken on the old offset: 01:30 UTC (03:30 CEST).
  const ShiftCalendar skipped = good(
      "timezone = \"Europe/Berlin\"\nshifts = [{days = \"sun\", start = \"02:30\", end = "
      "\"05:00\"}]\n");
  const auto k = shift_times(skipped, spring * kDayUs, (spring + 1) * kDayUs);
  ASSERT_EQ(k.size(), 1u);
  EXPECT_EQ(k[0].first, spring * kDayUs + kHourUs + kHourUs / 2);
  EXPECT_EQ(k[0].second, spring * kDayUs + 3 * kHourUs);
}

TEST(ZoneOffsets, EuropeBerlinChangesToTheSecondFrom1970To2100) {
  const auto start = std::chrono::steady_clock::now();
  const ZoneOffsets z = *zone_offsets("Europe/Berlin");
  // The cost is the first call's (later ones share the table); a figure, not a test.
  fmt::print("zone table Europe/Berlin: {} changes in {} ms\n", z.changes.size(),
             std::chrono::duration_cast<std::chrono::milliseconds>(
                 std::chrono::steady_clock::now() - start)
                 .count());
  const std::int64_t spring = date_of(2026, 3, 29) * 86'400 + 3600;  // 01:00 UTC
  const std::int64_t autumn = date_of(2026, 10, 25) * 86'400 + 3600;
  EXPECT_EQ(z.offset_at(spring - 1), 3600);
  EXPECT_EQ(z.offset_at(spring), 7200);
  EXPECT_EQ(z.offset_at(autumn - 1), 7200);
  EXPECT_EQ(z.offset_at(autumn), 3600);
  EXPECT_EQ(z.initial_s, 3600);
  // DST every year from 1980: two changes a year to 2100 (the zone's rule past its file).
  EXPECT_GE(z.changes.size(), 2u * (2100 - 1980 + 1));
  EXPECT_EQ(z.offset_at(date_of(2100, 7, 1) * 86'400), 7200);
  EXPECT_EQ(z.offset_at(date_of(2200, 7, 1) * 86'400), 3600);  // past 2100: the last offset
  EXPECT_EQ(zone_offsets("Europe/Berlin").get(), zone_offsets("Europe/Berlin").get());
}

// The table is probed daily (and bisected): the same as probed hourly for
// zones with unusual changes: half-hour summer time (Lord Howe), two hours
// (Troll), a skipped day (Apia, 2011-12-30), Ramadan suspensions a few weeks
// apart (Casablanca), midnight changes (Sao Paulo), a zone without DST.
TEST(ZoneOffsets, TheDailyProbesFindWhatHourlyProbesFind) {
  for (const char* name :
       {"Europe/Berlin", "America/Sao_Paulo", "Australia/Lord_Howe", "Antarctica/Troll",
        "Pacific/Apia", "Africa/Casablanca", "America/Nuuk", "Asia/Kolkata"}) {
    const ZoneOffsets daily = probe_zone_offsets(name, 86'400);
    EXPECT_EQ(daily, probe_zone_offsets(name, 3600)) << name;
    EXPECT_EQ(daily, *zone_offsets(name)) << name;
  }
  // A coarser step than the zone's closest changes misses some: the check can fail.
  EXPECT_NE(probe_zone_offsets("Africa/Casablanca", 120 * 86'400),
            probe_zone_offsets("Africa/Casablanca", 3600));
}

// Every zone of /usr/share/zoneinfo (but posix/ and right/, copies with
// other leap-second rules), daily against hourly, and the closest two
// changes of any zone; a check of the tzdata installed, minutes long:
//   USINA_ZONE_CHECK_ALL=1 build/tests/dnc_tests --gtest_filter='ZoneOffsets.EveryZone*'
TEST(ZoneOffsets, EveryZoneDailyIsHourly) {
  if (std::getenv("USINA_ZONE_CHECK_ALL") == nullptr)
    GTEST_SKIP() << "a check of the installed tzdata: set USINA_ZONE_CHECK_ALL=1";
  namespace fs = std::filesystem;
  const fs::path root = "/usr/share/zoneinfo";
  std::vector<std::string> names;
  for (const auto& e : fs::recursive_directory_iterator(root)) {
    const std::string name = fs::relative(e.path(), root).string();
    if (!e.is_regular_file() || name.starts_with("posix") || name.starts_with("right")) continue;
    if (timezone_error(name).empty()) names.push_back(name);
  }
  std::sort(names.begin(), names.end());
  std::int64_t closest = std::numeric_limits<std::int64_t>::max();
  std::string closest_zone;
  double daily_s = 0;
  double hourly_s = 0;
  for (const std::string& name : names) {
    const auto t0 = std::chrono::steady_clock::now();
    const ZoneOffsets daily = probe_zone_offsets(name, 86'400);
    const auto t1 = std::chrono::steady_clock::now();
    const ZoneOffsets hourly = probe_zone_offsets(name, 3600);
    const auto t2 = std::chrono::steady_clock::now();
    daily_s += std::chrono::duration<double>(t1 - t0).count();
    hourly_s += std::chrono::duration<double>(t2 - t1).count();
    EXPECT_EQ(daily, hourly) << name;
    for (std::size_t i = 1; i < hourly.changes.size(); ++i) {
      const std::int64_t gap = hourly.changes[i].at_s - hourly.changes[i - 1].at_s;
      if (gap < closest) {
        closest = gap;
        closest_zone = name;
      }
    }
  }
  fmt::print("{} zones: daily probes {:.1f} s, hourly {:.1f} s; closest changes {} s apart ({})\n",
             names.size(), daily_s, hourly_s, closest, closest_zone);
  EXPECT_GT(names.size(), 300u);
}

// The conversion must not read TZ once the calendar is read: the server
// never changes the environment while its threads run (setenv beside a
// getenv in libpq or OpenSSL is undefined behaviour). With TZ set to another
// zone, Berlin's clock changes still come out of the calendar's own table.
TEST(ShiftTimes, TheEnvironmentsTimeZoneIsNotReadAfterTheCalendarIsRead) {
  const ShiftCalendar night = good(
      "timezone = \"Europe/Berlin\"\nshifts = [{days = \"sat\", start = \"22:00\", end = "
      "\"06:00\"}]\n");
  const char* was = std::getenv("TZ");
  const std::optional<std::string> saved =
      was != nullptr ? std::optional(std::string(was)) : std::nullopt;
  ::setenv("TZ", ":America/Sao_Paulo", 1);
  ::tzset();
  // glibc now answers for Sao Paulo (-03:00, no DST since 2019)...
  const std::time_t t = date_of(2026, 3, 28) * 86'400;
  std::tm tm{};
  ::localtime_r(&t, &tm);
  EXPECT_EQ(tm.tm_gmtoff, -3 * 3600);
  // ...and the calendar still for Berlin: 22:00 CET is 21:00 UTC, the night 7 h and 9 h.
  const std::int64_t spring = date_of(2026, 3, 29);
  const std::int64_t autumn = date_of(2026, 10, 25);
  const auto s = shift_times(night, (spring - 1) * kDayUs, spring * kDayUs);
  ASSERT_EQ(s.size(), 1u);
  EXPECT_EQ(s[0].first, (spring - 1) * kDayUs + 21 * kHourUs);
  EXPECT_DOUBLE_EQ(hours(night, (spring - 2) * kDayUs, (spring + 2) * kDayUs), 7.0);
  EXPECT_DOUBLE_EQ(hours(night, (autumn - 2) * kDayUs, (autumn + 2) * kDayUs), 9.0);
  if (saved) {
    ::setenv("TZ", saved->c_str(), 1);
  } else {
    ::unsetenv("TZ");
  }
  ::tzset();
}

TEST(ShiftTimes, NoShiftStartsOnAHolidayButTheNightBeforeRunsIntoIt) {
  const ShiftCalendar c = good(
      "timezone = \"America/Sao_Paulo\"\nholidays = [\"2026-12-25\"]\n"
      "shifts = [{days = \"mon-fri\", start = \"06:00\", end = \"14:00\"},\n"
      "          {days = \"mon-fri\", start = \"22:00\", end = \"02:00\"}]\n");
  // Sao Paulo is UTC-3 (no summer time since 2019): 06:00-14:00 is 09:00-17:00 UTC,
  // 22:00-02:00 is 01:00-05:00 UTC the next day.
  const std::int64_t thu = date_of(2026, 12, 24);
  EXPECT_DOUBLE_EQ(day_hours(c, thu), 8.0 + 4.0);  // its day, and Wednesday's night
  EXPECT_DOUBLE_EQ(day_hours(c, thu + 1), 4.0);    // the holiday: Thursday's night only
  EXPECT_DOUBLE_EQ(day_hours(c, thu + 2), 0.0);    // Saturday: the holiday had no night
  EXPECT_DOUBLE_EQ(day_hours(c, thu + 3), 0.0);    // Sunday
}

TEST(CalendarDays, BerlinsChangeDaysAre23And25HoursFromLocalMidnight) {
  const ZoneOffsets* berlin = zone_offsets("Europe/Berlin").get();
  const std::int64_t spring = date_of(2026, 3, 29);
  const auto march = calendar_days(berlin, spring - 1, spring + 1);
  ASSERT_EQ(march.size(), 3u);
  // Midnight CET is 23:00 UTC the day before; midnight CEST 22:00 UTC.
  EXPECT_EQ(march[0].start_us, (spring - 1) * kDayUs - kHourUs);
  EXPECT_EQ(march[1].date, spring);
  EXPECT_EQ(march[1].start_us, spring * kDayUs - kHourUs);
  EXPECT_EQ(march[1].end_us - march[1].start_us, 23 * kHourUs);
  EXPECT_EQ(march[2].start_us, (spring + 1) * kDayUs - 2 * kHourUs);
  EXPECT_EQ(march[0].end_us - march[0].start_us, kDayUs);
  EXPECT_EQ(march[2].end_us - march[2].start_us, kDayUs);
  const std::int64_t autumn = date_of(2026, 10, 25);
  const auto october = calendar_days(berlin, autumn, autumn);
  ASSERT_EQ(october.size(), 1u);
  EXPECT_EQ(october[0].start_us, autumn * kDayUs - 2 * kHourUs);
  EXPECT_EQ(october[0].end_us - october[0].start_us, 25 * kHourUs);
  // Without a zone: UTC days.
  const auto utc = calendar_days(nullptr, spring, spring);
  EXPECT_EQ(utc[0].start_us, spring * kDayUs);
  EXPECT_EQ(utc[0].end_us, (spring + 1) * kDayUs);
  // 23:30 UTC on the 28th is already the 29th in Berlin.
  EXPECT_EQ(calendar_date(berlin, spring * kDayUs - kHourUs / 2), spring);
  EXPECT_EQ(calendar_date(nullptr, spring * kDayUs - kHourUs / 2), spring - 1);
  EXPECT_EQ(calendar_date(berlin, spring * kDayUs - kHourUs - 1), spring - 1);
}

// Brazil's summer time began at midnight: on 2018-11-04 in Sao Paulo 00:00
// (-03) became 01:00 (-02), so the day starts at 01:00, 03:00 UTC.
TEST(CalendarDays, AMidnightTheClocksSkipIsTakenOnTheOldOffset) {
  const ZoneOffsets* sao_paulo = zone_offsets("America/Sao_Paulo").get();
  const std::int64_t d = date_of(2018, 11, 4);
  const auto days = calendar_days(sao_paulo, d - 1, d);
  ASSERT_EQ(days.size(), 2u);
  EXPECT_EQ(days[0].start_us, (d - 1) * kDayUs + 3 * kHourUs);
  EXPECT_EQ(days[1].start_us, d * kDayUs + 3 * kHourUs);
  EXPECT_EQ(days[1].end_us - days[1].start_us, 23 * kHourUs);
  EXPECT_EQ(calendar_date(sao_paulo, d * kDayUs + 3 * kHourUs), d);
  EXPECT_EQ(calendar_date(sao_paulo, d * kDayUs + 3 * kHourUs - 1), d - 1);
}

class ShiftUtilisationOnBothStores : public test::StoreTest {};

TEST_P(ShiftUtilisationOnBothStores, RunningInsideAndOutsideTheShifts) {
  const std::int64_t d = date_of(2026, 6, 2);  // a Tuesday
  now_us = (d + 2) * kDayUs;
  auto store = open();
  ASSERT_TRUE(store);
  const ShiftCalendar c = good(
      "timezone = \"UTC\"\nshifts = [{days = \"mon-fri\", start = \"06:00\", end = \"14:00\"}]\n");
  const std::int64_t t0 = d * kDayUs;
  // Feeding 05:00-07:00 (one hour in the shift), a control cycle of 30 min ending at 14:15.
  ASSERT_TRUE(record_activity(*store, "m1", "idle", t0));
  ASSERT_TRUE(record_activity(*store, "m1", "feeding", t0 + 5 * kHourUs));
  ASSERT_TRUE(record_activity(*store, "m1", "idle", t0 + 7 * kHourUs));
  ASSERT_TRUE(
      record_control_part(*store, {"m1", t0 + 14 * kHourUs + kHourUs / 4, kHourUs / 2, 1, "", ""}));
  const TimeSpans shifts = shift_times(c, t0, t0 + 2 * kDayUs);
  auto days = machine_days(*store, "m1", d, d + 1, &shifts);
  ASSERT_TRUE(days) << days.error().message;
  EXPECT_DOUBLE_EQ((*days)[0].scheduled_seconds, 8 * 3600.0);
  EXPECT_DOUBLE_EQ((*days)[0].running_in_shift_seconds, 3600.0 + 900.0);
  EXPECT_DOUBLE_EQ((*days)[0].seconds.at("feeding"), 2 * 3600.0);
  EXPECT_DOUBLE_EQ((*days)[1].running_in_shift_seconds, 0.0);
  // Without shifts nothing is scheduled.
  auto plain = machine_days(*store, "m1", d, d);
  ASSERT_TRUE(plain);
  EXPECT_DOUBLE_EQ((*plain)[0].scheduled_seconds, 0.0);
}

// Local days of Europe/Berlin around both 2026 changes: 2026-03-29 has 23 h,
// 2026-10-25 has 25 h, and a part printed at 00:30 local on the 29th (23:30
// UTC on the 28th) counts on the 29th.
TEST_P(ShiftUtilisationOnBothStores, BerlinDaysOf23And25HoursAroundTheClockChanges) {
  const std::int64_t spring = date_of(2026, 3, 29);
  const std::int64_t autumn = date_of(2026, 10, 25);
  now_us = (autumn + 5) * kDayUs;
  auto store = open();
  ASSERT_TRUE(store);
  const ZoneOffsets* berlin = zone_offsets("Europe/Berlin").get();
  // Idle from the 27th, feeding from 20:00 UTC on the 28th to 02:00 UTC on the 30th.
  ASSERT_TRUE(record_activity(*store, "m1", "idle", (spring - 2) * kDayUs));
  ASSERT_TRUE(record_activity(*store, "m1", "feeding", spring * kDayUs - 4 * kHourUs));
  ASSERT_TRUE(record_activity(*store, "m1", "idle", (spring + 1) * kDayUs + 2 * kHourUs));
  ASSERT_TRUE(record_control_part(*store, {"m1", spring * kDayUs - kHourUs / 2, 0, 1, "", ""}));
  const auto march = machine_days(*store, "m1", calendar_days(berlin, spring - 1, spring + 1));
  ASSERT_TRUE(march) << march.error().message;
  ASSERT_EQ(march->size(), 3u);
  EXPECT_DOUBLE_EQ((*march)[0].seconds.at("feeding"), 3 * 3600.0);  // 20:00-23:00 UTC
  EXPECT_DOUBLE_EQ((*march)[0].seconds.at("idle"), 21 * 3600.0);
  EXPECT_EQ((*march)[0].parts, 0);
  EXPECT_DOUBLE_EQ((*march)[1].seconds.at("feeding"), 23 * 3600.0);  // the whole short day
  EXPECT_DOUBLE_EQ((*march)[1].known_seconds, 23 * 3600.0);
  EXPECT_DOUBLE_EQ((*march)[1].length_seconds(), 23 * 3600.0);
  EXPECT_EQ((*march)[1].parts, 1);
  EXPECT_DOUBLE_EQ((*march)[2].seconds.at("feeding"), 4 * 3600.0);  // 22:00-02:00 UTC
  // The same records in UTC days: the part is on the 28th.
  const auto utc = machine_days(*store, "m1", spring - 1, spring);
  ASSERT_TRUE(utc);
  EXPECT_EQ((*utc)[0].parts, 1);
  EXPECT_DOUBLE_EQ((*utc)[1].seconds.at("feeding"), 24 * 3600.0);
  // October: feeding from 21:00 UTC on the 24th to 00:00 UTC on the 26th.
  ASSERT_TRUE(record_activity(*store, "m1", "feeding", autumn * kDayUs - 3 * kHourUs));
  ASSERT_TRUE(record_activity(*store, "m1", "idle", (autumn + 1) * kDayUs));
  const auto october = machine_days(*store, "m1", calendar_days(berlin, autumn - 1, autumn + 1));
  ASSERT_TRUE(october) << october.error().message;
  EXPECT_DOUBLE_EQ((*october)[0].seconds.at("feeding"), 3600.0);  // 21:00-22:00 UTC
  EXPECT_DOUBLE_EQ((*october)[1].seconds.at("feeding"), 25 * 3600.0);
  EXPECT_DOUBLE_EQ((*october)[1].known_seconds, 25 * 3600.0);
  EXPECT_DOUBLE_EQ((*october)[1].length_seconds(), 25 * 3600.0);
  EXPECT_DOUBLE_EQ((*october)[2].seconds.at("feeding"), 3600.0);  // 23:00-00:00 UTC
}

USINA_STORE_BACKENDS(ShiftUtilisationOnBothStores);

// A server whose mill-1 works Berlin's early shift, every day 01:00-04:00,
// with 2026-03-30 (a Monday), 04-01 and 04-02 holidays.
Control start_with_calendar(RunningServer& s, bool with_calendar) {
  auto pair = open_pty_pair(s.io());
  EXPECT_TRUE(pair) << pair.error();
  Control c;
  c.link = std::move(pair->master);
  c.sim = std::make_shared<SimCnc>(s.io(), *c.link, SimCncConfig{});
  c.sim->start();
  ServerConfig config;
  config.machines.push_back(pty_machine("mill-1", pair->slave_path, 115200));
  if (with_calendar) {
    config.machines[0].calendar = good(
        "timezone = \"Europe/Berlin\"\nholidays = [\"2026-03-30\", \"2026-04-01\", "
        "\"2026-04-02\"]\n"
        "shifts = [{days = \"mon-sun\", start = \"01:00\", end = \"04:00\"}]\n");
    config.machines[0].calendar->source = "server";
  }
  s.start(config);
  return c;
}

TEST(ApiShiftUtilisation, ScheduledAndInShiftSecondsPerUtcDayAroundTheClockChange) {
  RunningServer s;
  Control control = start_with_calendar(s, true);
  const std::int64_t sat = date_of(2026, 3, 28);
  // The test's records go through the server's loop, which owns the store.
  const bool recorded = s.on_loop([&] {
    Store& store = s.server().store();
    const std::pair<std::int64_t, const char*> log[] = {{sat * kDayUs, "idle"},
                                                        {sat * kDayUs + kHourUs / 2, "feeding"},
                                                        {sat * kDayUs + 2 * kHourUs, "idle"},
                                                        {(sat + 1) * kDayUs + kHourUs, "feeding"},
                                                        {(sat + 1) * kDayUs + 3 * kHourUs, "idle"},
                                                        {(sat + 3) * kDayUs, "off"}};
    bool ok = true;
    for (const auto& [at, what] : log)
      ok = record_activity(store, "mill-1", what, at).has_value() && ok;
    return ok;
  });
  ASSERT_TRUE(recorded);
  const ApiClient c = s.client();
  const std::string oper = c.log_in("oper", usina::test::kPassword);
  const auto r = c.get("/api/machines/mill-1/utilisation?from=2026-03-28&to=2026-03-30", oper);
  ASSERT_EQ(r.status, 200) << r.body;
  const auto j = r.json();
  EXPECT_EQ(j["calendar"]["timezone"], "Europe/Berlin");
  const auto& days = j["days"];
  ASSERT_EQ(days.size(), 3u);
  // Saturday: 00:00-03:00 UTC planned; 00:30-02:00 ran, all in the shift.
  EXPECT_DOUBLE_EQ(days[0]["scheduled_seconds"].get<double>(), 3 * 3600.0);
  EXPECT_DOUBLE_EQ(days[0]["running_in_shift_seconds"].get<double>(), 1.5 * 3600.0);
  EXPECT_DOUBLE_EQ(days[0]["running_outside_shift_seconds"].get<double>(), 0.0);
  EXPECT_DOUBLE_EQ(days[0]["shift_utilisation"].get<double>(), 0.5);
  EXPECT_DOUBLE_EQ(days[0]["utilisation"].get<double>(), 1.5 * 3600.0 / 86400.0);  // as before
  // Sunday, the change: 2 h planned (the holiday's shift would have begun
  // at 23:00 UTC), 1 h of the 2 run in it.
  EXPECT_DOUBLE_EQ(days[1]["scheduled_seconds"].get<double>(), 2 * 3600.0);
  EXPECT_DOUBLE_EQ(days[1]["running_in_shift_seconds"].get<double>(), 3600.0);
  EXPECT_DOUBLE_EQ(days[1]["running_outside_shift_seconds"].get<double>(), 3600.0);
  EXPECT_DOUBLE_EQ(days[1]["shift_utilisation"].get<double>(), 0.5);
  // Monday the 30th is a holiday: its shift (23:00 UTC on Sunday to 02:00)
  // is not planned; the UTC day holds only Tuesday's first hour (01:00
  // summer time is 23:00 UTC), not run.
  EXPECT_DOUBLE_EQ(days[2]["scheduled_seconds"].get<double>(), 3600.0);
  EXPECT_DOUBLE_EQ(days[2]["shift_utilisation"].get<double>(), 0.0);
  EXPECT_DOUBLE_EQ(j["shift_utilisation"].get<double>(), 2.5 / 6.0);
  // 1 and 2 April are holidays: UTC 1 April has no shift at all.
  const auto none = c.get("/api/machines/mill-1/utilisation?from=2026-04-01&to=2026-04-01", oper);
  ASSERT_EQ(none.status, 200);
  EXPECT_DOUBLE_EQ(none.json()["days"][0]["scheduled_seconds"].get<double>(), 0.0);
  EXPECT_TRUE(none.json()["days"][0]["shift_utilisation"].is_null());
  EXPECT_TRUE(none.json()["shift_utilisation"].is_null());
}

// days=local: the same records as above in Berlin's days. Saturday the
// 28th runs from 23:00 UTC on the 27th, Sunday the 29th is 23 h, and the
// early shift (01:00-04:00) is 2 h on it; Sunday 25 October is 25 h, its
// shift 4 h.
TEST(ApiShiftUtilisation, DaysInTheCalendarsZoneAre23And25HoursLong) {
  RunningServer s;
  Control control = start_with_calendar(s, true);
  const std::int64_t sat = date_of(2026, 3, 28);
  const bool recorded = s.on_loop([&] {
    Store& store = s.server().store();
    const std::pair<std::int64_t, const char*> log[] = {{sat * kDayUs, "idle"},
                                                        {sat * kDayUs + kHourUs / 2, "feeding"},
                                                        {sat * kDayUs + 2 * kHourUs, "idle"},
                                                        {(sat + 1) * kDayUs + kHourUs, "feeding"},
                                                        {(sat + 1) * kDayUs + 3 * kHourUs, "idle"},
                                                        {(sat + 3) * kDayUs, "off"}};
    bool ok = true;
    for (const auto& [at, what] : log)
      ok = record_activity(store, "mill-1", what, at).has_value() && ok;
    return ok;
  });
  ASSERT_TRUE(recorded);
  const ApiClient c = s.client();
  const std::string oper = c.log_in("oper", usina::test::kPassword);
  const auto r =
      c.get("/api/machines/mill-1/utilisation?from=2026-03-28&to=2026-03-30&days=local", oper);
  ASSERT_EQ(r.status, 200) << r.body;
  const auto j = r.json();
  EXPECT_EQ(j["days_in"], "Europe/Berlin");
  EXPECT_TRUE(j["day_seconds"].is_null());
  const auto& days = j["days"];
  ASSERT_EQ(days.size(), 3u);
  EXPECT_EQ(days[1]["date"], "2026-03-29");
  EXPECT_DOUBLE_EQ(days[0]["day_seconds"].get<double>(), 24 * 3600.0);
  EXPECT_DOUBLE_EQ(days[1]["day_seconds"].get<double>(), 23 * 3600.0);
  // Saturday: the hour before 00:00 UTC has no record; 00:30-02:00 UTC ran, in the shift.
  EXPECT_DOUBLE_EQ(days[0]["unknown_seconds"].get<double>(), 3600.0);
  EXPECT_DOUBLE_EQ(days[0]["scheduled_seconds"].get<double>(), 3 * 3600.0);
  EXPECT_DOUBLE_EQ(days[0]["running_in_shift_seconds"].get<double>(), 1.5 * 3600.0);
  // Sunday: 01:00 CET to 04:00 CEST is 2 h; 01:00-03:00 UTC ran (03:00-05:00 CEST), 1 h in it.
  EXPECT_DOUBLE_EQ(days[1]["scheduled_seconds"].get<double>(), 2 * 3600.0);
  EXPECT_DOUBLE_EQ(days[1]["running_seconds"].get<double>(), 2 * 3600.0);
  EXPECT_DOUBLE_EQ(days[1]["running_in_shift_seconds"].get<double>(), 3600.0);
  EXPECT_DOUBLE_EQ(days[1]["utilisation"].get<double>(), 2.0 / 23.0);
  // Monday the 30th is a holiday: nothing planned in its local day.
  EXPECT_DOUBLE_EQ(days[2]["scheduled_seconds"].get<double>(), 0.0);
  EXPECT_TRUE(days[2]["shift_utilisation"].is_null());
  EXPECT_DOUBLE_EQ(j["utilisation"].get<double>(), 3.5 / 71.0);
  const auto autumn =
      c.get("/api/machines/mill-1/utilisation?from=2026-10-25&to=2026-10-25&days=local", oper);
  ASSERT_EQ(autumn.status, 200) << autumn.body;
  const auto october = autumn.json();
  const auto& sunday = october["days"][0];
  EXPECT_DOUBLE_EQ(sunday["day_seconds"].get<double>(), 25 * 3600.0);
  EXPECT_DOUBLE_EQ(sunday["scheduled_seconds"].get<double>(), 4 * 3600.0);
  // Without days (or days=utc) the answer is the UTC one of the test above.
  const auto plain =
      c.get("/api/machines/mill-1/utilisation?from=2026-03-29&to=2026-03-29&days=utc", oper).json();
  EXPECT_EQ(plain["days_in"], "UTC");
  EXPECT_DOUBLE_EQ(plain["day_seconds"].get<double>(), 86400.0);
  EXPECT_DOUBLE_EQ(plain["days"][0]["scheduled_seconds"].get<double>(), 2 * 3600.0);
  EXPECT_EQ(c.get("/api/machines/mill-1/utilisation?days=berlin", oper).status, 400);
}

TEST(ApiShiftUtilisation, LocalDaysWithoutACalendarAre400WithTheReason) {
  RunningServer s;
  Control control = start_with_calendar(s, false);
  const ApiClient c = s.client();
  const std::string oper = c.log_in("oper", usina::test::kPassword);
  const auto r = c.get("/api/machines/mill-1/utilisation?days=local", oper);
  EXPECT_EQ(r.status, 400);
  EXPECT_NE(r.body.find("mill-1 has none"), std::string::npos) << r.body;
  EXPECT_EQ(c.get("/api/machines/mill-1/utilisation?days=utc", oper).status, 200);
}

TEST(ApiShiftUtilisation, WithoutACalendarTheAnswerHasNoShiftFields) {
  RunningServer s;
  Control control = start_with_calendar(s, false);
  const ApiClient c = s.client();
  const std::string oper = c.log_in("oper", usina::test::kPassword);
  const auto j =
      c.get("/api/machines/mill-1/utilisation?from=2026-03-28&to=2026-03-28", oper).json();
  EXPECT_TRUE(j["calendar"].is_null());
  EXPECT_FALSE(j.contains("shift_utilisation"));
  EXPECT_FALSE(j["days"][0].contains("scheduled_seconds"));
  EXPECT_FALSE(j["days"][0].contains("shift_utilisation"));
  EXPECT_TRUE(j["days"][0].contains("utilisation"));
}

}  // namespace
}  // namespace usina::dnc
