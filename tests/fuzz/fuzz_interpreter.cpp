// libFuzzer target for the whole gcode front end: the input is a program,
// run by the interpreter into a NullSink with small limits, so a runaway
// loop or recursion ends quickly as a diagnostic. Every diagnostic is
// rendered (as `usina check` does) and then discarded, so the renderer's
// use of locations is fuzzed too.
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>

#include "canon/sink.hpp"
#include "core/diagnostic.hpp"
#include "core/source.hpp"
#include "gcode/interp/interpreter.hpp"
#include "input_limits.hpp"
#include "render_and_discard.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  usina::core::SourceManager sources;
  usina::fuzz::RenderAndDiscard diags(sources);
  std::string text(reinterpret_cast<const char*>(data), size);
  const std::uint32_t id =
      sources.add(usina::core::SourceFile::from_string("<fuzz>", std::move(text)));

  usina::gcode::InterpOptions opts;
  // Bounds low enough that a loop-heavy input ends well inside the hang limit
  // under ASan on a loaded CI machine (100,000 took 1.5-5 s); all loops
  // together are bounded, so nested loops end too; fewer for a long input.
  opts.max_loop_iterations = usina::fuzz::iterations_for(10'000, size);
  opts.max_total_iterations = usina::fuzz::iterations_for(20'000, size);
  opts.max_call_depth = 20;
  // No subroutine path: a fuzzed `o<name> call` must never touch the file system.
  opts.subroutine_path.clear();

  usina::canon::NullSink sink;
  usina::gcode::Interpreter interp(sources, std::move(opts), sink, diags);
  interp.run(id);
  return 0;
}
