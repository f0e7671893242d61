// libFuzzer target for the fanuc dialect: the input is a program run by the
// Macro B front end (gcode::find_dialect("fanuc")) into a NullSink with
// small limits, every diagnostic rendered and discarded. The first byte
// picks the dialect's options, so they are fuzzed too.
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "canon/sink.hpp"
#include "core/diagnostic.hpp"
#include "core/source.hpp"
#include "gcode/dialect.hpp"

namespace {

class RenderAndDiscard final : public usina::core::DiagnosticSink {
 public:
  explicit RenderAndDiscard(const usina::core::SourceManager& sources) : sources_(sources) {}

  void report(usina::core::Diagnostic d) override {
    const std::string text = usina::core::render(d, sources_);
    (void)text;
  }

 private:
  const usina::core::SourceManager& sources_;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace usina;
  const gcode::Dialect* fanuc = gcode::find_dialect("fanuc");
  std::vector<std::string> given;
  if (size > 0) {
    const std::uint8_t bits = data[0];
    if (bits & 1u) given.emplace_back("decimal_point=fanuc");
    if (bits & 2u) given.emplace_back("program_digits=8");
  }
  gcode::OptionValues values;
  if (gcode::resolve_options(*fanuc, given, values)) return 0;

  core::SourceManager sources;
  RenderAndDiscard diags(sources);
  std::string text(reinterpret_cast<const char*>(data), size);
  const std::uint32_t id = sources.add(core::SourceFile::from_string("<fuzz>", std::move(text)));

  gcode::InterpOptions opts;
  opts.max_loop_iterations = 10'000;
  opts.max_total_iterations = 1'000;  // loops, jumps and M98 L repeats
  opts.max_call_depth = 20;
  opts.subroutine_path.clear();
  if (size > 0 && (data[0] & 8u)) opts.ignore_cutter_comp = true;

  canon::NullSink sink;
  auto runner = fanuc->make_runner(
      gcode::RunContext{sources, std::move(opts), std::move(values), sink, diags});
  runner->run(id);
  return 0;
}
