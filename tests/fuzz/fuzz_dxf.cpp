// libFuzzer target for the DXF reader: the input is a drawing's bytes, read
// by cam::read_dxf_text as `usina gen from-dxf`, `pocket --dxf` and `profile
// --dxf` read their drawing (usina's line and group checks, then dxflib, then
// the entities to paths, splines approximated). The first byte picks the
// options: bit 0 reads only layer CUT, bit 1 the finest spline tolerance.
// Any input must give paths or diagnostics, never a crash or a hang.
// (Chaining the paths is left out: cam::chain is quadratic in entities whose
// ends coincide, a known finding of issue 11 for its own fix.)
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "cam/dxf_import.hpp"
#include "core/diagnostic.hpp"

namespace {

class DiscardDiagnostics final : public usina::core::DiagnosticSink {
 public:
  void report(usina::core::Diagnostic d) override { (void)d; }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace usina;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const std::uint8_t bits = size > 0 ? data[0] : 0;
  cam::DxfOptions options;
  if ((bits & 1u) != 0) options.layer = "CUT";
  if ((bits & 2u) != 0) options.spline_tolerance = cam::kMinSplineTolerance;
  DiscardDiagnostics diags;
  (void)cam::read_dxf_text(text, "<fuzz>", options, diags);
  return 0;
}
