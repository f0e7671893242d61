// Google Benchmark of `usina stats`'s back end alone (no G-code): the stats
// sink with its motion planner on a canon stream like a surfacing program's
// (0.25 mm feeds over a wavy surface, a helical half-circle at each row end),
// with trapezoidal and S-curve profiles, and the look-ahead planner alone on
// a corner every move. Throughput is in ops per second. Never asserts times.
#include <cmath>
#include <vector>

#include <benchmark/benchmark.h>

#include "canon/op.hpp"
#include "core/diagnostic.hpp"
#include "sim/planner.hpp"
#include "sim/stats.hpp"

namespace {

using usina::canon::Op;

// A zig-zag raster of about `count` ops.
std::vector<Op> surfacing_ops(int count) {
  constexpr int kPointsPerRow = 600;
  std::vector<Op> ops;
  ops.reserve(static_cast<std::size_t>(count) + 4);
  ops.push_back({usina::canon::Spindle{12000, usina::canon::SpindleDir::Cw}, {}});
  double y = 0.0;
  int i = 0;
  bool forward = true;
  while (static_cast<int>(ops.size()) < count) {
    if (i == kPointsPerRow) {
      const double x = forward ? 150.0 : 0.0;
      usina::canon::Arc a;
      a.to = {x, y + 0.5, -1.5};
      a.center = {x, y + 0.25, -1.5};
      a.normal = {0, 0, 1};
      a.turn = forward ? 1 : -1;
      a.f = 1500.0;
      ops.push_back({a, {}});
      y += 0.5;
      i = 0;
      forward = !forward;
      continue;
    }
    ++i;
    const double x = forward ? i * 0.25 : 150.0 - i * 0.25;
    const double z = -1.5 + std::sin(x / 15.0) * std::cos(y / 20.0);
    ops.push_back({usina::canon::Feed{{x, y, z}, 1500.0, {}}, {}});
  }
  ops.push_back({usina::canon::ProgramEnd{}, {}});
  return ops;
}

usina::sim::MachineProfile profile(double jerk) {
  usina::sim::MachineProfile m = usina::sim::default_machine_profile();
  for (std::size_t i = 0; i < 3; ++i)
    m.axes[i].jerk = jerk;
  return m;
}

void run_stats(benchmark::State& state, double jerk) {
  const std::vector<Op> ops = surfacing_ops(static_cast<int>(state.range(0)));
  const usina::sim::MachineProfile m = profile(jerk);
  for (auto _ : state) {
    usina::core::DiagnosticList diags;
    usina::sim::StatsSink sink(m, {}, diags);
    for (const Op& op : ops)
      sink.on(op);
    sink.finish();
    benchmark::DoNotOptimize(sink.report().total.cutting_s);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(ops.size()));
}

void BM_StatsTrapezoid(benchmark::State& state) {
  run_stats(state, 0.0);
}

void BM_StatsSCurve(benchmark::State& state) {
  run_stats(state, 20000.0);
}

// The planner alone: a 90° corner every 1 mm.
void BM_PlannerCorners(benchmark::State& state) {
  const auto n = state.range(0);
  for (auto _ : state) {
    usina::sim::Planner p({});
    for (std::int64_t k = 0; k < n; ++k) {
      usina::sim::PlannedMove m;
      m.length = 1.0;
      m.start_dir = m.end_dir =
          (k % 2 == 0) ? usina::core::Vec3{1, 0, 0} : usina::core::Vec3{0, 1, 0};
      m.cruise = 50.0;
      m.kin = {500.0, 0.0};
      p.add(m);
    }
    p.stop();
    benchmark::DoNotOptimize(p.accounts()[0].lookahead_s);
  }
  state.SetItemsProcessed(state.iterations() * n);
}

}  // namespace

BENCHMARK(BM_StatsTrapezoid)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StatsSCurve)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PlannerCorners)->Arg(100000)->Unit(benchmark::kMillisecond);
