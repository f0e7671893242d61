// The stock a revision leaves, frame by frame (web_stock.hpp). Two runs of
// the interpreter: the first counts the moves (the frames are equal shares
// of them) and measures the program's box; the second cuts the stock and
// takes the frames. Interpreting is cheap beside sweeping, and the moves
// are never held: a program of millions of blocks costs its map only.
#include "dnc/web_stock.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "canon/sink.hpp"
#include "core/source.hpp"
#include "gcode/dialect.hpp"
#include "sim/stats.hpp"
#include "sim/stock/removal_rate.hpp"
#include "sim/stock/simulator.hpp"

namespace usina::dnc {
namespace {

namespace stock = sim::stock;
using core::Vec3;
using nlohmann::json;

// The tool's diameter as the simulator takes it: the settings' shape, the
// tool change's diameter, or the default 6 mm end mill.
double diameter_of(const StockSettings& s, int tool, std::optional<double> from_program) {
  if (const auto it = s.tools.find(tool); it != s.tools.end()) return it->second.diameter;
  if (from_program && *from_program > 0.0) return *from_program;
  return stock::ToolShape{}.diameter;
}

// The first run: the moves, and the box the cuts need.
class Survey final : public canon::Sink {
 public:
  explicit Survey(const StockSettings& s) : settings_(s) {}

  void on(const canon::Op& op) override {
    if (const auto* t = std::get_if<canon::ToolChange>(&op.kind)) {
      radius_ = diameter_of(settings_, t->tool, t->diameter) / 2.0;
      return;
    }
    if (!canon::is_motion(op.kind)) return;
    ++moves;
    std::visit([&](const auto& m) { move(m); }, op.kind);
  }

  std::uint64_t moves = 0;

  // The box of the cuts (docs/web.md, "The stock"); none without a cut.
  std::optional<stock::StockBox> box() const {
    if (!cut_) return std::nullopt;
    const double top = deepest_ < 0.0 ? 0.0 : highest_start_;
    const double r = widest_;
    return stock::StockBox{hi_.x - lo_.x + 2.0 * r, hi_.y - lo_.y + 2.0 * r, top - deepest_ + 1.0,
                           Vec3{lo_.x - r, lo_.y - r, top}};
  }

 private:
  void move(const canon::Feed& m) { cut(m.to); }

  void move(const canon::Spline& m) {
    cut(m.to);
    for (const Vec3& p : m.points)
      take(p);
  }

  // An arc stays within its centre's box of its radius.
  void move(const canon::Arc& a) {
    const double r = std::hypot(a.to.x - a.center.x, a.to.y - a.center.y);
    cut(a.to);
    take({a.center.x - r, a.center.y - r, a.to.z});
    take({a.center.x + r, a.center.y + r, a.to.z});
  }

  template <class Other>
  void move(const Other& m) {
    if constexpr (requires { m.to; }) pos_ = m.to;
  }

  void cut(const Vec3& to) {
    highest_start_ = cut_ ? std::max(highest_start_, pos_.z) : pos_.z;
    deepest_ = cut_ ? std::min({deepest_, pos_.z, to.z}) : std::min(pos_.z, to.z);
    if (!cut_) lo_ = hi_ = pos_;
    cut_ = true;
    take(pos_);
    take(to);
    widest_ = std::max(widest_, radius_);
    pos_ = to;
  }

  void take(const Vec3& p) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return;
    lo_ = {std::min(lo_.x, p.x), std::min(lo_.y, p.y), std::min(lo_.z, p.z)};
    hi_ = {std::max(hi_.x, p.x), std::max(hi_.y, p.y), std::max(hi_.z, p.z)};
  }

  const StockSettings& settings_;
  Vec3 pos_{};
  Vec3 lo_{}, hi_{};
  bool cut_ = false;
  double deepest_ = 0.0, highest_start_ = 0.0;
  double radius_ = diameter_of(settings_, 0, std::nullopt) / 2.0;
  double widest_ = 0.0;
};

template <class T>
void put(std::string& out, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));  // the server is little-endian (x86_64, aarch64)
  out.append(bytes, sizeof(T));
}

struct FrameRecord {
  std::uint64_t moves = 0;
  std::uint32_t line = 0;
  double removed_mm3 = 0.0;
  std::uint64_t runs = 0;
  std::uint64_t cells = 0;
  std::uint64_t offset = 0;  // of its runs, from the data's start
  std::uint64_t op = 0;      // the canon ops taken when it was, numbered as stats numbers them
  double time_s = 0.0;       // when the planner has run those ops
};

// The second run: the simulator cuts, and at each share of the moves the
// cells whose depth or mark changed since the frame before are written.
class Frames final : public canon::Sink {
 public:
  Frames(stock::StockSimulator& sim, sim::StatsSink& timer, stock::HeightMap& map,
         std::uint64_t moves, std::uint32_t frames, std::uint64_t max_bytes)
      : max_bytes_(max_bytes),
        sim_(sim),
        timer_(timer),
        map_(map),
        moves_total_(std::max<std::uint64_t>(moves, 1)),
        frames_(static_cast<std::uint32_t>(std::min<std::uint64_t>(frames, moves_total_))),
        unit_(map.box().height / 65535.0),
        depth_(map.nx() * map.ny(), 0),
        mark_(map.nx() * map.ny(), stock::kUncut) {}

  void on(const canon::Op& op) override {
    ++ops_;
    sim_.on(op);
    timer_.on(op);
    if (!canon::is_motion(op.kind)) return;
    ++moves_;
    line_ = op.src.line;
    if (!too_large() && records.size() + 1 < frames_ && moves_ >= due()) take();
  }

  // The frames so far are past the answer's bound: no more are taken.
  bool too_large() const { return data.size() > max_bytes_; }

  // The last frame: the map as the run left it, however far it went.
  void last() {
    if (!too_large()) take();
  }

  double depth_unit() const { return unit_; }

  // From the planner (StatsSink::observe): `seconds` of op `op` ran. The
  // planner runs behind the cut (its look-ahead): a frame's time is known
  // once an op after its last has been timed.
  void timed(std::uint64_t op, double seconds) {
    while (timed_ < records.size() && records[timed_].op < op)
      records[timed_++].time_s = clock_;
    clock_ += seconds;
  }

  // The end of the run: the frames not yet timed end with it.
  void finish_times() {
    while (timed_ < records.size())
      records[timed_++].time_s = clock_;
  }

  std::vector<FrameRecord> records;
  std::string data;

 private:
  // The moves at which the next frame is due: an equal share each.
  std::uint64_t due() const {
    const std::uint64_t k = records.size() + 1;
    return (k * moves_total_ + frames_ - 1) / frames_;
  }

  std::uint16_t depth_at(std::size_t i, std::size_t j) const {
    const double d = -static_cast<double>(map_.at(i, j)) / unit_;
    return static_cast<std::uint16_t>(std::clamp(std::lround(d), 0L, 65535L));
  }

  void take() {
    FrameRecord f{moves_, line_, sim_.removed_mm3(), 0, 0, data.size(), ops_, 0.0};
    std::vector<std::uint32_t> runs;
    std::vector<std::uint16_t> depths;
    std::vector<std::uint8_t> marks;
    for (std::size_t j = 0; j < map_.ny(); ++j) {
      for (std::size_t i = 0; i < map_.nx(); ++i) {
        const std::size_t k = j * map_.nx() + i;
        const std::uint16_t d = depth_at(i, j);
        // A cell cut by less than half a unit is shown uncut: its mark
        // would cost bytes for nothing (a profile run at the top's Z).
        const std::uint8_t m = d == 0 ? stock::kUncut : map_.mark(i, j);
        if (d == depth_[k] && m == mark_[k]) continue;
        depth_[k] = d;
        mark_[k] = m;
        if (!runs.empty() && runs[runs.size() - 2] + runs.back() == k) {
          ++runs.back();
        } else {
          runs.push_back(static_cast<std::uint32_t>(k));
          runs.push_back(1);
        }
        depths.push_back(d);
        marks.push_back(m);
      }
    }
    f.runs = runs.size() / 2;
    f.cells = depths.size();
    write(runs, depths, marks);
    records.push_back(f);
  }

  void write(const std::vector<std::uint32_t>& runs, const std::vector<std::uint16_t>& depths,
             const std::vector<std::uint8_t>& marks) {
    for (const std::uint32_t v : runs)
      put(data, v);
    for (const std::uint16_t v : depths)
      put(data, v);
    data.append(reinterpret_cast<const char*>(marks.data()), marks.size());
    data.append((4 - data.size() % 4) % 4, '\0');  // the next frame's runs aligned
  }

  std::uint64_t max_bytes_;
  stock::StockSimulator& sim_;
  sim::StatsSink& timer_;
  stock::HeightMap& map_;
  std::uint64_t moves_total_;
  std::uint32_t frames_;
  double unit_;
  std::vector<std::uint16_t> depth_;
  std::vector<std::uint8_t> mark_;
  std::uint64_t moves_ = 0;
  std::uint32_t line_ = 0;
  std::uint64_t ops_ = 0;
  std::size_t timed_ = 0;  // the frames before it have their time
  double clock_ = 0.0;     // s the planner has run
};

// One run of the revision's text through its dialect into `sink`.
struct Run {
  bool ok = false;
};

Run run_program(std::string_view text, const gcode::Dialect& dialect, std::uint64_t max_ops,
                canon::Sink& sink) {
  core::ErrorCount diags;
  core::SourceManager sources;
  const std::uint32_t id =
      sources.add(core::SourceFile::from_string("<revision>", std::string(text)));
  canon::OpBudget budget(sink, max_ops, diags);
  auto runner = dialect.make_runner(gcode::RunContext{
      sources, gcode::InterpOptions{}, gcode::default_options(dialect), budget, diags});
  const bool ok = runner->run(id);
  budget.finish();
  return {ok && diags.errors() == 0};
}

std::string refusal(unsigned status, const std::string& why) {
  return json{{"error", why}, {"status", status}}.dump();
}

json tools_json(const stock::StockSimulator& sim) {
  json out = json::array();
  for (const stock::ToolVolume& t : sim.tools()) {
    out.push_back({{"tool", t.tool},
                   {"shape", stock::shape_name(t.shape)},
                   {"diameter_mm", t.shape.diameter},
                   {"removed_mm3", t.removed_mm3}});
  }
  return out;
}

json checks_json(const stock::StockSimulator& sim) {
  constexpr std::size_t kListed = 100;
  json out = json::array();
  for (std::size_t i = 0; i < std::min(kListed, sim.checks().size()); ++i) {
    const stock::Check& c = sim.checks()[i];
    out.push_back(
        {{"code", core::code_name(c.code)}, {"line", c.loc.line}, {"message", c.message}});
  }
  return out;
}

json frames_json(const std::vector<FrameRecord>& records) {
  json out = json::array();
  for (const FrameRecord& f : records) {
    out.push_back({{"moves", f.moves},
                   {"line", f.line},
                   {"removed_mm3", f.removed_mm3},
                   {"runs", f.runs},
                   {"cells", f.cells},
                   {"offset", f.offset},
                   {"time_s", f.time_s}});
  }
  return out;
}

// The removal rate's peak over the program's time (docs/simulate.md, "Removal rate").
json peak_json(const stock::RemovalTimeline& t) {
  const std::size_t peak = t.peak_bin();
  if (t.bins().empty() || !(t.bins()[peak] > 0.0)) return nullptr;
  return {{"mm3_per_min", t.bins()[peak] / t.bin_s() * 60.0},
          {"at_s", static_cast<double>(peak) * t.bin_s()},
          {"bin_s", t.bin_s()}};
}

json header_json(const stock::HeightMap& map, const stock::StockSimulator& sim,
                 const Frames& frames, const stock::RemovalTimeline& timeline, std::uint64_t moves,
                 bool from_program, bool complete) {
  const stock::StockBox& b = map.box();
  return {{"version", kStockVersion},
          {"stock",
           {{"box", {b.width, b.length, b.height}},
            {"origin", {b.origin.x, b.origin.y, b.origin.z}},
            {"from_program", from_program}}},
          {"cells", {map.nx(), map.ny()}},
          {"cell_mm", {map.dx(), map.dy()}},
          {"top_mm", map.top()},
          {"bottom_mm", map.bottom()},
          {"depth_unit_mm", frames.depth_unit()},
          {"moves", moves},
          {"time_s", timeline.total_s()},
          {"peak_removal", peak_json(timeline)},
          {"complete", complete},
          {"removed_mm3", sim.removed_mm3()},
          {"rapid_removed_mm3", sim.rapid_removed_mm3()},
          {"tools", tools_json(sim)},
          {"checks", checks_json(sim)},
          {"checks_total", sim.checks().size()},
          {"frames", frames_json(frames.records)}};
}

std::string assemble(const json& header, const std::string& data) {
  std::string text = header.dump(-1, ' ', false, json::error_handler_t::replace);
  text.append((4 - text.size() % 4) % 4, ' ');
  std::string out;
  out.reserve(12 + text.size() + data.size());
  put(out, kStockMagic);
  put(out, kStockVersion);
  put(out, static_cast<std::uint32_t>(text.size()));
  out += text;
  out += data;
  return out;
}

}  // namespace

bool is_stock_answer(std::string_view bytes) {
  std::uint32_t magic = 0;
  if (bytes.size() < 12) return false;
  std::memcpy(&magic, bytes.data(), sizeof magic);
  return magic == kStockMagic;
}

std::string encode_stock(std::string_view text, const StockSettings& settings) {
  const gcode::Dialect* dialect = gcode::find_dialect(settings.dialect);
  if (dialect == nullptr)
    return refusal(422, "the program's dialect '" + settings.dialect + "' is unknown");
  Survey survey(settings);
  run_program(text, *dialect, settings.max_ops, survey);
  // A program that cuts nothing gets a small block at its zero.
  const stock::StockBox box =
      settings.box ? *settings.box
                   : survey.box().value_or(stock::StockBox{10.0, 10.0, 1.0, {-5.0, -5.0, 0.0}});
  // An explicit box's resolution was checked against the bounds with it.
  const double resolution =
      settings.box && settings.resolution
          ? *settings.resolution
          : fitting_resolution(box, settings.frames, settings.limits, settings.resolution);
  auto map = stock::HeightMap::make(box, resolution);
  if (!map)
    return refusal(422, "the program's own stock cannot be simulated: " + map.error() +
                            "; give stock=box:WxLxH and origin=X,Y,Z");
  stock::SimulateOptions options;
  options.tools = settings.tools;
  core::ErrorCount checks;  // the simulator's checks are in its list
  stock::StockSimulator sim(*map, options, checks);
  // The times: stats' planner on the generic mill (a revision has no machine).
  core::DiagnosticList timing_checks;
  sim::StatsSink timer(sim::default_machine_profile(), {}, timing_checks);
  stock::RemovalTimeline timeline;
  sim.set_timeline(&timeline);
  Frames frames(sim, timer, *map, survey.moves, settings.frames, settings.limits.max_answer_bytes);
  timer.observe([&](std::uint64_t op, double seconds) {
    timeline.timed(op, seconds);
    frames.timed(op, seconds);
  });
  const Run run = run_program(text, *dialect, settings.max_ops, frames);
  timer.finish();
  timeline.finish();
  frames.last();
  frames.finish_times();
  if (frames.too_large()) {
    return refusal(413, fmt::format("the frames passed the {} bytes an answer may have at {} of {} "
                                    "moves: ask for fewer frames or a coarser resolution",
                                    settings.limits.max_answer_bytes, frames.records.back().moves,
                                    survey.moves));
  }
  return assemble(
      header_json(*map, sim, frames, timeline, survey.moves, !settings.box.has_value(), run.ok),
      frames.data);
}

}  // namespace usina::dnc
