// libFuzzer target for one dialect's runner, named at compile time by
// USINA_FUZZ_DIALECT (scripts/fuzz.sh builds fuzz_romi, fuzz_fanuc and
// fuzz_grbl from this file with -DUSINA_FUZZ_DIALECT="romi" and so on). The
// input is a program run by gcode::find_dialect(USINA_FUZZ_DIALECT)'s runner
// into a NullSink with small limits, every diagnostic rendered and discarded.
// The first byte picks the dialect's options, so they are fuzzed too.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "canon/sink.hpp"
#include "core/diagnostic.hpp"
#include "core/source.hpp"
#include "gcode/dialect.hpp"
#include "input_limits.hpp"
#include "render_and_discard.hpp"

#ifndef USINA_FUZZ_DIALECT
#  error "define USINA_FUZZ_DIALECT as the dialect's name, e.g. -DUSINA_FUZZ_DIALECT=\"romi\""
#endif

namespace {

// What the first byte may turn on for a dialect: bit i sets settings[i] (an
// empty one is no setting); bit 3 sets InterpOptions::ignore_cutter_comp
// where the dialect has cutter compensation to ignore.
struct FuzzedOptions {
  std::string_view dialect;
  std::array<std::string_view, 3> settings;
  bool comp_bit = false;
};

constexpr std::array kFuzzedOptions{
    // romi: jumps, calls, pattern points and pocket rings are what the limits stop.
    FuzzedOptions{
        "romi", {"lowercase_incremental=off", "motion_cancels_cycle=on", "comp_radius=tool"}, true},
    // fanuc: loops, jumps and M98 L repeats.
    FuzzedOptions{"fanuc", {"decimal_point=fanuc", "program_digits=8", ""}, false},
    // grbl: Grbl's line checks, then the interpreter, rerun after each refused line.
    FuzzedOptions{"grbl", {"after_error=stop", "grbl_m7=on", ""}, false},
};

constexpr const FuzzedOptions* find_fuzzed(std::string_view dialect) {
  for (const FuzzedOptions& f : kFuzzedOptions) {
    if (f.dialect == dialect) return &f;
  }
  return nullptr;
}

constexpr const FuzzedOptions* kFuzzed = find_fuzzed(USINA_FUZZ_DIALECT);
static_assert(kFuzzed != nullptr, "USINA_FUZZ_DIALECT names no dialect of kFuzzedOptions");

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace usina;
  const gcode::Dialect* dialect = gcode::find_dialect(kFuzzed->dialect);
  if (dialect == nullptr) __builtin_trap();  // the table names a dialect usina lacks
  const std::uint8_t bits = size > 0 ? data[0] : 0;
  std::vector<std::string> given;
  for (std::size_t i = 0; i < kFuzzed->settings.size(); ++i) {
    if ((bits & (1u << i)) != 0 && !kFuzzed->settings[i].empty()) {
      given.emplace_back(kFuzzed->settings[i]);
    }
  }
  auto values = gcode::resolve_options(*dialect, given);
  if (!values) return 0;

  core::SourceManager sources;
  fuzz::RenderAndDiscard diags(sources);
  std::string text(reinterpret_cast<const char*>(data), size);
  const std::uint32_t id = sources.add(core::SourceFile::from_string("<fuzz>", std::move(text)));

  gcode::InterpOptions opts;
  opts.max_loop_iterations = fuzz::iterations_for(10'000, size);  // fewer for a long input
  opts.max_total_iterations = fuzz::iterations_for(1'000, size);
  opts.max_call_depth = 20;
  opts.subroutine_path.clear();  // a fuzzed call must never touch the file system
  if (kFuzzed->comp_bit && (bits & 8u) != 0) opts.ignore_cutter_comp = true;

  canon::NullSink sink;
  auto runner = dialect->make_runner(
      gcode::RunContext{sources, std::move(opts), std::move(*values), sink, diags});
  runner->run(id);
  return 0;
}
