// libFuzzer target for the readers of `usina job`'s TOML files: the input is
// a job file, a tool library or a materials file (the first byte picks
// which), read as `usina job` reads it (toml++, then usina's keys, types,
// ranges and cross-checks, each problem a diagnostic at its line). Any input
// must give a value or diagnostics, never a crash, a hang or a non-finite
// number in what was read. The job's paths are only joined to a folder
// here, never opened (load_job opens them; the DXF reader has its own target).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "core/diagnostic.hpp"
#include "job/job_file.hpp"
#include "job/materials.hpp"
#include "job/tools.hpp"

namespace {

class DiscardDiagnostics final : public usina::core::DiagnosticSink {
 public:
  void report(usina::core::Diagnostic d) override { (void)d; }
};

void trap_unless_finite(double v) {
  if (!std::isfinite(v)) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace usina;
  if (size == 0) return 0;
  const std::string_view text(reinterpret_cast<const char*>(data) + 1, size - 1);
  DiscardDiagnostics diags;
  switch (data[0] % 3) {
  case 0: {
    const auto job = job::read_job(text, 0, "/nonexistent-fuzz-folder", diags);
    if (!job) break;
    trap_unless_finite(job->safe_z);
    for (const job::Operation& op : job->operations)
      trap_unless_finite(op.height + op.at[0] + op.at[1] + op.depth);
    break;
  }
  case 1: {
    const auto tools = job::read_tool_library(text, 0, diags);
    if (tools)
      for (const job::Tool& t : *tools)
        trap_unless_finite(t.diameter + t.max_bore);
    break;
  }
  default: (void)job::read_materials(text, 0, diags); break;
  }
  return 0;
}
