// Google Benchmark of the gcode front end alone, on a generated 3D surfacing
// program like bench/gen_surfacing.py's: the parser (lexer included) over
// every line, the interpreter into a NullSink (what `usina check` does), and
// the interpreter into a JSONL TraceWriter on /dev/null (`usina trace`).
// Throughput is in bytes of G-code per second. Never asserts times.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <string_view>

#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include "canon/sink.hpp"
#include "canon/trace_writer.hpp"
#include "core/diagnostic.hpp"
#include "core/source.hpp"
#include "gcode/block.hpp"
#include "gcode/interp/interpreter.hpp"
#include "gcode/parser.hpp"
#include "gcode/program_index.hpp"

namespace {

double surface(double x, double y) {
  return -1.5 + std::sin(x / 15.0) * std::cos(y / 20.0);
}

// A zig-zag raster of `blocks` blocks: G1 X Y Z 0.25 mm apart, a helical
// G2/G3 half-circle at each row end, a short R arc and a feed change now and then.
std::string surfacing_program(int blocks) {
  constexpr int kPointsPerRow = 600;
  constexpr double kStep = 0.25;
  constexpr double kStepover = 0.5;
  fmt::memory_buffer out;
  fmt::format_to(std::back_inserter(out),
                 "G21 G90 G17 G54 G94\nS12000 M3\nG0 Z5\nG1 Z-1.5 F1500\n");
  double y = 0.0;
  int row = 0;
  int i = 0;
  for (int n = 0; n < blocks; ++n) {
    const bool forward = row % 2 == 0;
    if (i == kPointsPerRow) {
      const double x = forward ? kPointsPerRow * kStep : 0.0;
      y += kStepover;
      fmt::format_to(std::back_inserter(out), "{} X{:.4f} Y{:.4f} Z{:.4f} I0 J{:.4f}\n",
                     forward ? "G3" : "G2", x, y, surface(x, y), kStepover / 2);
      ++row;
      i = 0;
      continue;
    }
    ++i;
    const double x = forward ? i * kStep : (kPointsPerRow - i) * kStep;
    if (n % 97 == 50) {
      fmt::format_to(std::back_inserter(out), "G2 X{:.4f} Y{:.4f} Z{:.4f} R1\n", x, y,
                     surface(x, y));
    } else if (n % 211 == 100) {
      fmt::format_to(std::back_inserter(out), "G1 X{:.4f} Y{:.4f} Z{:.4f} F{}\n", x, y,
                     surface(x, y), 1000 + 100 * (n % 7));
    } else {
      fmt::format_to(std::back_inserter(out), "G1 X{:.4f} Y{:.4f} Z{:.4f}\n", x, y, surface(x, y));
    }
  }
  fmt::format_to(std::back_inserter(out), "M5\nM30\n");
  return fmt::to_string(out);
}

const std::string& program(int blocks) {
  static std::string small = surfacing_program(10'000);
  static std::string large = surfacing_program(100'000);
  return blocks <= 10'000 ? small : large;
}

class CountingDiagnostics final : public usina::core::DiagnosticSink {
 public:
  void report(usina::core::Diagnostic d) override {
    if (d.severity == usina::core::Severity::Error) ++errors;
  }

  int errors = 0;
};

void BM_ParseBlocks(benchmark::State& state) {
  const std::string& text = program(static_cast<int>(state.range(0)));
  CountingDiagnostics diags;
  usina::gcode::Block block;
  for (auto _ : state) {
    std::uint64_t offset = 0;
    std::uint32_t line = 1;
    while (offset < text.size()) {
      const usina::gcode::LineView lv = usina::gcode::line_at(text, offset);
      usina::gcode::parse_block(lv.text, {0, line++, offset}, block, diags);
      benchmark::DoNotOptimize(block.words.data());
      offset = lv.next;
    }
  }
  if (diags.errors > 0) state.SkipWithError("the generated program has syntax errors");
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) *
                          static_cast<std::int64_t>(text.size()));
}

BENCHMARK(BM_ParseBlocks)->Arg(10'000)->Arg(100'000)->Unit(benchmark::kMillisecond);

// One whole run of the interpreter on the program into `sink`.
bool interpret(const std::string& text, usina::canon::Sink& sink, CountingDiagnostics& diags) {
  usina::core::SourceManager sources;
  const std::uint32_t id = sources.add(usina::core::SourceFile::from_string("<bench>", text));
  usina::gcode::Interpreter interp(sources, usina::gcode::InterpOptions{}, sink, diags);
  return interp.run(id);
}

void BM_InterpretCheck(benchmark::State& state) {
  const std::string& text = program(static_cast<int>(state.range(0)));
  CountingDiagnostics diags;
  usina::canon::NullSink sink;
  for (auto _ : state) {
    if (!interpret(text, sink, diags)) state.SkipWithError("the generated program has errors");
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) *
                          static_cast<std::int64_t>(text.size()));
}

BENCHMARK(BM_InterpretCheck)->Arg(10'000)->Arg(100'000)->Unit(benchmark::kMillisecond);

void BM_InterpretTraceJsonl(benchmark::State& state) {
  const std::string& text = program(static_cast<int>(state.range(0)));
  CountingDiagnostics diags;
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> null(std::fopen("/dev/null", "w"), &std::fclose);
  if (!null) {
    state.SkipWithError("cannot open /dev/null");
    return;
  }
  for (auto _ : state) {
    usina::canon::TraceWriter writer(null.get(), usina::canon::TraceFormat::Jsonl);
    if (!interpret(text, writer, diags)) state.SkipWithError("the generated program has errors");
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) *
                          static_cast<std::int64_t>(text.size()));
}

BENCHMARK(BM_InterpretTraceJsonl)->Arg(10'000)->Arg(100'000)->Unit(benchmark::kMillisecond);

void BM_ProgramIndex(benchmark::State& state) {
  const std::string& text = program(static_cast<int>(state.range(0)));
  auto file = usina::core::SourceFile::from_string("<bench>", text);
  for (auto _ : state) {
    auto index = usina::gcode::ProgramIndex::build(*file, 0);
    benchmark::DoNotOptimize(index.entries().data());
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) *
                          static_cast<std::int64_t>(text.size()));
}

BENCHMARK(BM_ProgramIndex)->Arg(100'000)->Unit(benchmark::kMillisecond);

}  // namespace
