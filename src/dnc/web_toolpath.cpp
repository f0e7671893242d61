#include "dnc/web_toolpath.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <deque>
#include <limits>

#include "canon/sink.hpp"
#include "core/arc.hpp"
#include "core/source.hpp"
#include "gcode/dialect.hpp"

namespace usina::dnc {
namespace {

using core::Vec3;

// A viewer's chord: fine enough to look round at any zoom a shop uses,
// coarse enough that a big arc is not thousands of vertices.
double chord_tolerance(double radius) {
  return std::max(0.01, radius * 1e-3);
}

core::Plane plane_of(const Vec3& normal) {
  const double ax = std::abs(normal.x);
  const double ay = std::abs(normal.y);
  const double az = std::abs(normal.z);
  if (az >= ax && az >= ay) return core::Plane::XY;
  return ay >= ax ? core::Plane::ZX : core::Plane::YZ;
}

// Every motion op as vertices, the others for the tool in the spindle.
class VertexSink final : public canon::Sink {
 public:
  VertexSink(ToolpathResult& r, std::uint64_t max_collected) : r_(r), max_(max_collected) {
    r_.vertices.push_back({});  // the start: the origin, as stats and draw take it
  }

  void on(const canon::Op& op) override {
    ++op_;  // numbered as the timer numbers them: every op, from 1
    if (const auto* t = std::get_if<canon::ToolChange>(&op.kind)) {
      tool_ = t->tool < 0 ? 0u : static_cast<std::uint32_t>(t->tool);
      return;
    }
    if (!canon::is_motion(op.kind)) return;
    ++r_.moves;
    const std::size_t first = r_.vertices.size();
    const std::uint32_t line = op.src.line;
    std::visit([&](const auto& m) { move(m, line); }, op.kind);
    untimed_.push_back({op_, first, r_.vertices.size()});
  }

  // The timer's report (sim::StatsSink::observe): op `op` and the ops
  // before it still untimed took `seconds` more; their vertices get times
  // spread evenly over them (an arc's chords are equal).
  void timed(std::uint64_t op, double seconds) {
    if (!(seconds >= 0.0) || !std::isfinite(seconds)) seconds = 0.0;
    const double from = clock_;
    clock_ += seconds;
    std::size_t first = 0;
    std::size_t end = 0;
    bool any = false;
    while (!untimed_.empty() && untimed_.front().op <= op) {
      if (!any) first = untimed_.front().first;
      end = untimed_.front().end;
      any = true;
      untimed_.pop_front();
    }
    if (!any) return;  // a wait: the next vertex starts later
    const double n = static_cast<double>(end - first);
    for (std::size_t i = first; i < end; ++i)
      r_.vertices[i].t =
          static_cast<float>(from + seconds * static_cast<double>(i - first + 1) / n);
  }

  // After the timer's finish: what it never timed ends at the last time.
  void close() {
    for (const Untimed& u : untimed_)
      for (std::size_t i = u.first; i < u.end; ++i)
        r_.vertices[i].t = static_cast<float>(clock_);
    untimed_.clear();
    r_.total_s = clock_;
  }

 private:
  void move(const canon::Traverse& m, std::uint32_t line) { add(m.to, PathKind::Rapid, line); }

  void move(const canon::Feed& m, std::uint32_t line) { add(m.to, PathKind::Feed, line); }

  void move(const canon::Probe& m, std::uint32_t line) { add(m.to, PathKind::Probe, line); }

  void move(const canon::Spline& m, std::uint32_t line) {
    for (const Vec3& p : m.points)
      add(p, PathKind::Spline, line);
    if (m.points.empty() || !(m.points.back() == m.to)) add(m.to, PathKind::Spline, line);
  }

  void move(const canon::Arc& a, std::uint32_t line) {
    const core::Plane plane = plane_of(a.normal);
    const double axial = a.normal[core::axes_of(plane).axial];
    const bool ccw = (a.turn > 0) == (axial > 0);
    const core::Vec2 s = core::in_plane(pos_, plane);
    const core::Vec2 c = core::in_plane(a.center, plane);
    const double radius = std::hypot(s.x - c.x, s.y - c.y);
    const double sweep =
        core::arc_sweep(s, core::in_plane(a.to, plane), c, ccw, std::max(1, std::abs(a.turn)));
    for (const Vec3& p :
         core::linearize_arc(pos_, a.to, a.center, plane, sweep, chord_tolerance(radius)))
      add(p, PathKind::Arc, line);
  }

  template <class Other>
  void move(const Other&, std::uint32_t) {}

  void add(const Vec3& p, PathKind kind, std::uint32_t line) {
    pos_ = p;
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return;
    if (r_.vertices.size() >= max_) {
      r_.truncated = true;
      return;
    }
    r_.vertices.push_back({static_cast<float>(p.x), static_cast<float>(p.y),
                           static_cast<float>(p.z), kind, tool_, line});
  }

  // A motion op's vertices [first, end) that wait for the timer.
  struct Untimed {
    std::uint64_t op;
    std::size_t first;
    std::size_t end;
  };

  ToolpathResult& r_;
  std::uint64_t max_;
  Vec3 pos_{};
  std::uint32_t tool_ = 0;
  std::uint64_t op_ = 0;
  std::deque<Untimed> untimed_;  // as long as the planner's look-ahead
  double clock_ = 0.0;
};

float gap(const PathVertex& a, const PathVertex& b) {
  return std::max({std::abs(a.x - b.x), std::abs(a.y - b.y), std::abs(a.z - b.z)});
}

// One merging pass at `tol`.
std::vector<PathVertex> merge_close(const std::vector<PathVertex>& in, float tol) {
  std::vector<PathVertex> out;
  out.reserve(in.size() / 2 + 2);
  for (std::size_t i = 0; i < in.size(); ++i) {
    const PathVertex& v = in[i];
    const bool last = i + 1 == in.size();
    if (out.size() > 1 && !last) {  // never into the start
      const PathVertex& k = out.back();
      if (k.kind == v.kind && k.tool == v.tool && gap(k, v) < tol) continue;
    }
    out.push_back(v);
  }
  return out;
}

std::vector<PathVertex> sample_evenly(const std::vector<PathVertex>& in, std::uint32_t n) {
  std::vector<PathVertex> out;
  out.reserve(n);
  const double step = static_cast<double>(in.size() - 1) / static_cast<double>(n - 1);
  for (std::uint32_t i = 0; i < n; ++i) {
    const auto at = static_cast<std::size_t>(std::llround(step * static_cast<double>(i)));
    out.push_back(in[std::min(at, in.size() - 1)]);
  }
  return out;
}

template <class T>
void put(std::string& out, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));  // the server is little-endian (x86_64, aarch64)
  out.append(bytes, sizeof(T));
}

}  // namespace

ToolpathResult program_toolpath(std::string_view text, const ToolpathSettings& settings) {
  ToolpathResult r;
  const gcode::Dialect* dialect = gcode::find_dialect(settings.dialect);
  if (dialect == nullptr) {
    r.ok = false;
    r.vertices.push_back({});
    return r;
  }
  core::ErrorCount diags;
  core::SourceManager sources;
  const std::uint32_t id =
      sources.add(core::SourceFile::from_string("<revision>", std::string(text)));
  gcode::OptionValues options = gcode::default_options(*dialect);
  VertexSink vertices(r, settings.max_collected);
  // The timer's own checks (travel, feeds) are the revision check's business.
  core::ErrorCount timing_checks;
  sim::StatsSink timer(settings.profile, sim::StatsOptions{}, timing_checks);
  timer.observe([&vertices](std::uint64_t op, double s) { vertices.timed(op, s); });
  canon::TeeSink both({&vertices, &timer});  // the vertices first: the timer reports after
  canon::OpBudget budget(both, settings.max_ops, diags);
  auto runner = dialect->make_runner(
      gcode::RunContext{sources, gcode::InterpOptions{}, std::move(options), budget, diags});
  r.ok = runner->run(id) && diags.errors() == 0;
  budget.finish();
  vertices.close();
  r.collected = r.vertices.size();
  r.vertices = decimate(r.vertices, settings.max_vertices);
  return r;
}

std::vector<PathVertex> decimate(const std::vector<PathVertex>& path, std::uint32_t max_vertices) {
  max_vertices = std::max<std::uint32_t>(max_vertices, 2);
  if (path.size() <= max_vertices) return path;
  float lo = std::numeric_limits<float>::max();
  float hi = std::numeric_limits<float>::lowest();
  for (const PathVertex& v : path) {
    lo = std::min({lo, v.x, v.y, v.z});
    hi = std::max({hi, v.x, v.y, v.z});
  }
  // From 1/4096 of the extent: below a pixel on any screen.
  float tol = std::max((hi - lo) / 4096.0f, 1e-4f);
  std::vector<PathVertex> out = merge_close(path, tol);
  for (int pass = 0; pass < 24 && out.size() > max_vertices; ++pass) {
    tol *= 2.0f;
    out = merge_close(out, tol);
  }
  if (out.size() > max_vertices) out = sample_evenly(out, max_vertices);
  return out;
}

std::string encode_toolpath(const ToolpathResult& r) {
  const auto n = static_cast<std::uint32_t>(r.vertices.size());
  std::string out;
  out.reserve(kToolpathHeaderBytes + std::size_t{n} * kToolpathVertexBytes);
  std::uint32_t flags = 0;
  if (r.vertices.size() < r.collected) flags |= 1u;  // decimated
  if (r.truncated) flags |= 2u;
  if (!r.ok) flags |= 4u;  // the run stopped on an error: the path ends there
  put(out, kToolpathMagic);
  put(out, kToolpathVersion);
  put(out, n);
  put(out, flags);
  put(out, r.moves);
  std::array<float, 3> lo{0, 0, 0};
  std::array<float, 3> hi{0, 0, 0};
  for (std::size_t i = 0; i < r.vertices.size(); ++i) {
    const PathVertex& v = r.vertices[i];
    const std::array<float, 3> p{v.x, v.y, v.z};
    for (std::size_t a = 0; a < 3; ++a) {
      lo[a] = i == 0 ? p[a] : std::min(lo[a], p[a]);
      hi[a] = i == 0 ? p[a] : std::max(hi[a], p[a]);
    }
  }
  for (float f : lo)
    put(out, f);
  for (float f : hi)
    put(out, f);
  put(out, r.total_s);
  for (const PathVertex& v : r.vertices) {
    put(out, v.x);
    put(out, v.y);
    put(out, v.z);
  }
  for (const PathVertex& v : r.vertices)
    put(out, v.line);
  for (const PathVertex& v : r.vertices)
    put(out, v.tool);
  for (const PathVertex& v : r.vertices)
    put(out, v.t);
  for (const PathVertex& v : r.vertices)
    put(out, static_cast<std::uint8_t>(v.kind));
  return out;
}

}  // namespace usina::dnc
