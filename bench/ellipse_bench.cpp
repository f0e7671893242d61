// Google Benchmark of the elliptical pocket (issue 5's speed target: an
// ellipse at resolution 0.001 mm on a 200 mm pocket generates in under a
// second): the DDA ellipse alone, one depth level of the pocket into a
// NullSink (the canon ops), and the same written by the rs274ngc post into
// memory. Items are points (DDA) or canon ops. Never asserts times.
#include <sstream>

#include <benchmark/benchmark.h>

#include "cam/ellipse_dda.hpp"
#include "cam/ellipse_pocket.hpp"
#include "canon/sink.hpp"
#include "core/diagnostic.hpp"
#include "post/post.hpp"

namespace {

using usina::cam::EllipsePocket;

// 200 mm long, 120 mm wide, one 5 mm level, a 10 mm tool at 5 mm stepover.
EllipsePocket pocket_200mm() {
  EllipsePocket p;
  p.rx = 100;
  p.ry = 60;
  p.depth = 5;
  p.ap = 5;
  p.cut.tool_diameter = 10;
  p.ae = 5;
  p.ae_finish = 0.5;
  p.resolution = 0.001;
  return p;
}

class CountingSink final : public usina::canon::Sink {
 public:
  void on(const usina::canon::Op&) override { ++ops; }

  long ops = 0;
};

void BM_DdaEllipse200mm(benchmark::State& state) {
  std::size_t points = 0;
  for (auto _ : state) {
    const auto e = usina::cam::dda_ellipse(100, 60, 0.001);
    points = e.size();
    benchmark::DoNotOptimize(e.data());
  }
  state.counters["points"] = static_cast<double>(points);
  state.SetItemsProcessed(state.iterations() * static_cast<long>(points));
}

BENCHMARK(BM_DdaEllipse200mm)->Unit(benchmark::kMillisecond);

void BM_EllipsePocket200mmCanon(benchmark::State& state) {
  const EllipsePocket p = pocket_200mm();
  long ops = 0;
  for (auto _ : state) {
    CountingSink sink;
    usina::cam::generate(p, sink);
    ops = sink.ops;
  }
  state.counters["ops"] = static_cast<double>(ops);
  state.SetItemsProcessed(state.iterations() * ops);
}

BENCHMARK(BM_EllipsePocket200mmCanon)->Unit(benchmark::kMillisecond);

void BM_EllipsePocket200mmRs274ngc(benchmark::State& state) {
  const EllipsePocket p = pocket_200mm();
  std::size_t bytes = 0;
  for (auto _ : state) {
    std::ostringstream out;
    usina::core::DiagnosticList diags;
    auto post = usina::post::make_post("rs274ngc", out, {}, diags);
    usina::cam::generate(p, *post);
    post->finish();
    bytes = out.str().size();
  }
  state.counters["bytes"] = static_cast<double>(bytes);
  state.SetBytesProcessed(state.iterations() * static_cast<long>(bytes));
}

BENCHMARK(BM_EllipsePocket200mmRs274ngc)->Unit(benchmark::kMillisecond);

}  // namespace
