// Where a restart may begin and the modal state there (resume_point.hpp).
#include "gcode/resume_point.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>

#include <fmt/format.h>

#include "core/diagnostic.hpp"
#include "core/source.hpp"
#include "gcode/dialect.hpp"
#include "gcode/resume_scan.hpp"

namespace usina::gcode {
namespace {

using Fail = tl::unexpected<std::string>;

// What the canon stream of the blocks before the start says.
class Observer final : public canon::Sink {
 public:
  void on(const canon::Op& op) override {
    std::visit([&](const auto& k) { take(k, op); }, op.kind);
  }

  std::optional<int> tool;
  std::optional<double> tool_diameter;  // mm
  double rpm = 0.0;
  canon::SpindleDir dir = canon::SpindleDir::Off;
  canon::Coolant coolant;
  std::optional<double> feed_mm;       // mm/min of the last feed move
  std::optional<double> feed_program;  // the last G93/G95 value
  bool moved = false;
  core::Vec3 pos;
  double max_z = 0.0;
  std::optional<int> first_change_to;  // set: the line of the first change to it
  std::optional<std::uint32_t> change_line;
  std::uint32_t main_file = 0;

 private:
  void move(const core::Vec3& to) {
    max_z = moved ? std::max(max_z, to.z) : to.z;
    moved = true;
    pos = to;
  }

  void rate(std::optional<double> f, const canon::ProgrammedFeed& p) {
    if (f) feed_mm = f;
    if (p.mode != canon::ProgrammedFeed::Mode::PerMinute) feed_program = p.value;
  }

  void take(const canon::Traverse& t, const canon::Op&) { move(t.to); }

  void take(const canon::Feed& f, const canon::Op&) {
    move(f.to);
    rate(f.f, f.programmed);
  }

  void take(const canon::Arc& a, const canon::Op&) {
    move(a.to);
    rate(a.f, a.programmed);
  }

  void take(const canon::Spline& s, const canon::Op&) {
    move(s.to);
    rate(s.f, s.programmed);
  }

  void take(const canon::Probe& p, const canon::Op&) { move(p.to); }

  void take(const canon::ToolChange& t, const canon::Op& op) {
    tool = t.tool;
    tool_diameter = t.diameter;
    if (first_change_to && *first_change_to == t.tool && !change_line && op.src.file == main_file)
      change_line = op.src.line;
  }

  void take(const canon::Spindle& s, const canon::Op&) {
    rpm = s.rpm;
    dir = s.dir;
  }

  void take(const canon::Coolant& c, const canon::Op&) { coolant = c; }

  template <class T>
  void take(const T&, const canon::Op&) {}
};

struct RunResult {
  bool ok = true;
  std::string error;
  std::optional<RunModes> modes;  // where the run ended
};

RunResult run_in_dialect(std::string text, const Dialect& dialect, Observer& obs) {
  core::SourceManager sources;
  core::DiagnosticList diags;
  const std::uint32_t id = sources.add(core::SourceFile::from_string("<program>", std::move(text)));
  obs.main_file = id;
  OptionValues options = default_options(dialect);
  canon::OpBudget budget(obs, 10'000'000, diags);
  auto runner =
      dialect.make_runner(RunContext{sources, InterpOptions{}, std::move(options), budget, diags});
  runner->run(id);
  for (const core::Diagnostic& d : diags.all()) {
    if (d.severity == core::Severity::Error)
      return {false, fmt::format("{} (line {})", d.message, d.loc.line), std::nullopt};
  }
  return {true, {}, runner->modes()};
}

tl::expected<std::size_t, std::string> start_index(std::string_view text, const Dialect& dialect,
                                                   const std::vector<ScanLine>& lines,
                                                   const ResumeStart& start) {
  switch (start.kind) {
  case ResumeStart::Kind::Line:
    if (start.value < 1 || static_cast<std::size_t>(start.value) > lines.size())
      return Fail(fmt::format("line {} is past the end of the program ({} lines)", start.value,
                              lines.size()));
    return static_cast<std::size_t>(start.value - 1);
  case ResumeStart::Kind::NWord:
    for (std::size_t i = 0; i < lines.size(); ++i)
      if (lines[i].n == start.value && !lines[i].in_sub && !lines[i].past_end) return i;
    return Fail(fmt::format("the program has no block N{} in its main part", start.value));
  case ResumeStart::Kind::Tool: {
    Observer obs;
    obs.first_change_to = static_cast<int>(start.value);
    run_in_dialect(std::string(text), dialect, obs);
    if (!obs.change_line)
      return Fail(fmt::format("tool T{} is never changed to in the program", start.value));
    return static_cast<std::size_t>(*obs.change_line - 1);
  }
  }
  return Fail("unknown start");
}

bool is_cycle(int g) {
  return g == 730 || g == 740 || g == 760 || (g >= 810 && g <= 890);
}

bool is_motion(int g) {
  return g == 0 || g == 10 || g == 20 || g == 30 || g == 800 || is_cycle(g);
}

// A word that moves the coordinate frame, first seen in the main part of
// the text before the start: "G10 at line 4". (The runner's modes see a
// G92 or a rotation wherever it was run; G10 writes parameters they do not
// show.)
std::optional<std::string> frame_word(const std::vector<ScanLine>& lines, std::size_t before,
                                      bool romi) {
  for (std::size_t i = 0; i < before && !romi; ++i) {
    if (lines[i].in_sub) continue;
    for (const int g : lines[i].g) {
      if (g == 100 || g == 920 || g == 521 || g == 520 || g == 680 || g == 510 || g == 511 ||
          g == 160)
        return fmt::format("G{:g} at line {}", g / 10.0, i + 1);
    }
  }
  return std::nullopt;
}

// The text the run before the start reads: the blocks before it, and for
// fanuc the programs after the main one (`O9 ... M99` after M30, called by
// an M98 before the start; the next O block ends the main program there).
std::string run_before(std::string_view text, const std::vector<ScanLine>& lines, std::size_t start,
                       std::string_view dialect) {
  std::string prefix(text.substr(0, lines[start].offset));
  if (dialect == "fanuc") {
    for (std::size_t i = start; i < lines.size(); ++i) {
      const std::string_view raw =
          lines[i].raw.substr(std::min(lines[i].raw.size(), lines[i].raw.find_first_not_of(" \t")));
      if (!raw.empty() && (raw[0] == 'O' || raw[0] == 'o' || raw[0] == ':'))
        return prefix + std::string(text.substr(lines[i].offset));
    }
  }
  if (!prefix.empty() && prefix[0] == '%' && dialect != "romi") prefix += "%\n";
  return prefix;
}

// The modes a restart writes back, from the runner that ran the program
// before the start.
void take_modes(const RunModes& r, canon::ResumeState& s) {
  s.inch = r.inch;
  s.plane = r.plane;
  s.incremental = r.incremental;
  s.work_offset = r.work_offset;
  if (r.length_h >= 0) s.length_offset = r.length_h;
  s.feed_mode = r.feed_mode;
}

std::string head_of(const std::vector<ScanLine>& lines, std::string_view dialect,
                    std::size_t start) {
  std::string head;
  std::size_t i = 0;
  auto blank = [&](std::size_t k) {
    return lines[k].raw.find_first_not_of(" \t\r") == std::string_view::npos;
  };
  while (i < lines.size() && blank(i))
    ++i;
  if (i < lines.size() && lines[i].raw.substr(0, 1) == "%")
    head += std::string(lines[i++].raw) + "\n";
  while (i < lines.size() && blank(i))
    ++i;
  if (dialect == "fanuc" && i < lines.size() && !lines[i].raw.empty() &&
      (lines[i].raw[0] == 'O' || lines[i].raw[0] == 'o' || lines[i].raw[0] == ':'))
    head += std::string(lines[i++].raw) + "\n";
  return i > start ? std::string() : head;
}

}  // namespace

std::optional<ResumeStart> parse_start_block(std::string_view text) {
  ResumeStart s;
  if (!text.empty() && (text[0] == 'N' || text[0] == 'n')) {
    s.kind = ResumeStart::Kind::NWord;
    text.remove_prefix(1);
  }
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), s.value);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size() || s.value < 0)
    return std::nullopt;
  return s;
}

tl::expected<ResumePoint, std::string> find_resume_point(std::string_view text,
                                                         std::string_view dialect_name,
                                                         const ResumeStart& start) {
  const Dialect* dialect = find_dialect(dialect_name);
  if (dialect == nullptr) return Fail(fmt::format("unknown dialect {}", dialect_name));
  const bool romi = dialect_name == "romi";
  const auto lines = scan_program(text, dialect_name);
  auto at = start_index(text, *dialect, lines, start);
  if (!at) return Fail(at.error());
  const ScanLine& first = lines[*at];
  const std::size_t line = *at + 1;
  if (first.past_end) return Fail(fmt::format("line {} is after the program's end", line));
  if (first.in_sub)
    return Fail(
        fmt::format("line {} is inside a subroutine: a restart cannot enter it "
                    "without its call; start at the block that calls it",
                    line));
  if (!first.inside.empty())
    return Fail(
        fmt::format("line {} is inside {}: its count or condition cannot be "
                    "restored; start at the block that opens it",
                    line, first.inside));
  ResumePoint p;
  for (std::size_t i = 0; i < *at; ++i) {
    if (lines[i].in_sub) p.definitions += std::string(lines[i].raw) + "\n";
  }
  if (const auto frame = frame_word(lines, *at, romi))
    return Fail(
        fmt::format("the program moves its coordinate frame before line {} ({}): "
                    "usina cannot restore it; start before that block",
                    line, *frame));
  Observer obs;
  std::string prefix = run_before(text, lines, *at, dialect_name);
  const RunResult before = run_in_dialect(std::move(prefix), *dialect, obs);
  if (!before.ok)
    return Fail(fmt::format("the program before line {} does not run: {}", line, before.error));
  const RunModes modes = before.modes.value_or(RunModes{});
  if (modes.frame_moved)
    return Fail(
        fmt::format("the program moves its coordinate frame before line {} (a G92 or "
                    "G52 offset, or a rotation, mirror or scale, is in force there): "
                    "usina cannot restore it; start before that block",
                    line));
  if (modes.offsets_written)
    return Fail(
        fmt::format("the program writes offsets before line {} (a G10, or a home, G92 or "
                    "work offset parameter, in a subroutine or macro): usina cannot restore "
                    "them; start before that block",
                    line));
  canon::ResumeState& s = p.state;
  take_modes(modes, s);
  for (const int g : first.g)
    if (is_motion(g)) s.block_has_motion = true;
  if (!s.block_has_motion && first.axis && is_cycle(modes.motion))
    return Fail(
        fmt::format("line {} continues the canned cycle G{:g} without restating it: "
                    "its R, Z and Q levels cannot be restored; start at the block "
                    "with the cycle's G word",
                    line, modes.motion / 10.0));
  if (!s.block_has_motion && first.axis && (modes.motion == 20 || modes.motion == 30))
    return Fail(
        fmt::format("line {} continues the arc mode G{} without restating it; "
                    "start at the block with its G word",
                    line, modes.motion / 10));
  if (s.feed_mode == 93)
    return Fail("inverse-time feed (G93) is in force: usina will not choose the plunge's time");
  if (modes.length_h == -2)
    return Fail(
        fmt::format("a G43.1 or G43.2 length offset is in force before line {}: usina "
                    "cannot write it back; start before that block",
                    line));
  s.motion = modes.motion == 0 ? 0 : 10;
  for (const int mc : first.m)
    if (mc == 6) s.start_block_changes_tool = true;
  s.line = static_cast<std::uint32_t>(line);
  s.n_word = first.n;
  if (start.kind == ResumeStart::Kind::Tool) s.by_tool = static_cast<int>(start.value);
  s.tool = obs.tool;
  s.tool_diameter_mm = obs.tool_diameter;
  s.rpm = obs.rpm;
  s.spindle = obs.dir;
  s.coolant = obs.coolant;
  const double per = s.inch ? 25.4 : 1.0;
  if (s.feed_mode == 94 && obs.feed_mm) s.feed = *obs.feed_mm / per;
  if (s.feed_mode == 95 && obs.feed_program) s.feed = obs.feed_program;
  s.moved = obs.moved;
  s.start = obs.pos / per;
  s.safe_z = std::max(obs.max_z, obs.pos.z) / per;
  p.head = head_of(lines, dialect_name, *at);
  p.offset = first.offset;
  return p;
}

}  // namespace usina::gcode
