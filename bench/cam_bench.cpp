// Google Benchmark of the cam front end on a generated 10,000-entity DXF
// drawing (issue 5: "a 10,000-entity DXF generates in under a second"): the
// drawing read by dxflib, its entities chained, and the whole of
// `usina gen from-dxf` up to the canon stream (read, chain, generate into a
// NullSink), on the line and offset by a tool radius. The post's G-code
// writing is timed with the whole command by bench/gen_sketch_dxf.py's file
// (see docs/cam.md). Never asserts times.
#include <cmath>
#include <sstream>
#include <string>

#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include "cam/chain.hpp"
#include "cam/dxf_import.hpp"
#include "cam/from_dxf.hpp"
#include "canon/sink.hpp"
#include "core/diagnostic.hpp"

namespace {

// A sketch of `n` entities, as seed 002's free-form sketch and a CAD outline
// mix them: LINEs (every third drawn backwards), an ARC every seventh
// entity; a zig-zag in rows of 100 entities, so 100 open contours.
std::string drawing(int n) {
  fmt::memory_buffer out;
  auto to = std::back_inserter(out);
  fmt::format_to(to, "0\nSECTION\n2\nENTITIES\n");
  for (int i = 0; i < n; ++i) {
    const double x = (i % 100) * 1.0;
    const double y = (i / 100) * 2.0 + ((i % 2) ? 0.5 : 0.0);
    const double x2 = x + 1.0;
    const double y2 = (i / 100) * 2.0 + ((i % 2) ? 0.0 : 0.5);
    if (i % 7 == 3) {
      // A half circle from (x, y) to (x2, y2)'s neighbourhood: centre the midpoint.
      const double cx = (x + x2) / 2, cy = (y + y2) / 2;
      const double r = std::hypot(x2 - x, y2 - y) / 2;
      const double a1 = std::atan2(y - cy, x - cx) * 180 / 3.141592653589793;
      fmt::format_to(to, "0\nARC\n8\nSKETCH\n10\n{}\n20\n{}\n30\n0\n40\n{}\n50\n{}\n51\n{}\n", cx,
                     cy, r, a1, a1 + 180);
    } else if (i % 3 == 2) {
      fmt::format_to(to, "0\nLINE\n8\nSKETCH\n10\n{}\n20\n{}\n30\n0\n11\n{}\n21\n{}\n31\n0\n", x2,
                     y2, x, y);
    } else {
      fmt::format_to(to, "0\nLINE\n8\nSKETCH\n10\n{}\n20\n{}\n30\n0\n11\n{}\n21\n{}\n31\n0\n", x, y,
                     x2, y2);
    }
  }
  fmt::format_to(to, "0\nENDSEC\n0\nEOF\n");
  return fmt::to_string(out);
}

const std::string& sketch() {
  static const std::string text = drawing(10000);
  return text;
}

std::vector<usina::cam::Path> read(usina::core::DiagnosticList& d) {
  std::istringstream in(sketch());
  return *usina::cam::read_dxf(in, "sketch", {}, d);
}

void BM_DxfRead10k(benchmark::State& state) {
  for (auto _ : state) {
    usina::core::DiagnosticList d;
    benchmark::DoNotOptimize(read(d));
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * sketch().size()));
}

BENCHMARK(BM_DxfRead10k)->Unit(benchmark::kMillisecond);

void BM_Chain10k(benchmark::State& state) {
  usina::core::DiagnosticList d;
  const auto entities = read(d);
  for (auto _ : state)
    benchmark::DoNotOptimize(usina::cam::chain(entities));
}

BENCHMARK(BM_Chain10k)->Unit(benchmark::kMillisecond);

// The whole generator: read, chain, canon ops; arg 1 offsets by a tool radius.
void BM_FromDxf10k(benchmark::State& state) {
  usina::cam::FromDxfOptions o;
  o.side = state.range(0) ? usina::cam::Side::Left : usina::cam::Side::On;
  o.cut.tool_diameter = 0.4;
  for (auto _ : state) {
    usina::core::DiagnosticList d;
    usina::canon::NullSink sink;
    const auto paths = usina::cam::chain(read(d));
    if (!usina::cam::generate_from_paths(paths, o, sink, d)) state.SkipWithError("failed");
  }
}

BENCHMARK(BM_FromDxf10k)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
