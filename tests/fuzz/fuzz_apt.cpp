// libFuzzer target for the APT reader (issue 15): the input is a part
// program read by apt::process as `usina apt` reads it (statements, symbols,
// geometry, motion into CL records), then every writer of its result: the
// record print (--format cldump), the canon stream (--format jsonl, into a
// NullSink) and the canonical forms (--canonical). The first byte picks the
// unit of the canon stream (bit 0: inches) and its circles (bit 1: chords,
// else arcs). Every diagnostic is rendered and discarded. Any input must
// give records or diagnostics, never a crash, a hang or a number that is not
// finite in the canon stream.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <variant>

#include "apt/canon_out.hpp"
#include "apt/geometry.hpp"
#include "apt/processor.hpp"
#include "canon/sink.hpp"
#include "core/source.hpp"
#include "finite_sink.hpp"
#include "render_and_discard.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace usina;
  const std::uint8_t bits = size > 0 ? data[0] : 0;
  core::SourceManager sources;
  fuzz::RenderAndDiscard diags(sources);
  std::string text(reinterpret_cast<const char*>(data), size);
  const std::uint32_t id = sources.add(core::SourceFile::from_string("<fuzz>", std::move(text)));
  const apt::AptResult result = apt::process(sources.get(id)->text(), id, diags);
  const std::string print = apt::record_print(result.records);
  (void)print;
  for (const apt::Definition& d : result.definitions) {
    for (double v : apt::canonical(d.geom)) {
      if (!std::isfinite(v)) __builtin_trap();  // a canonical form (a pattern's points) not finite
    }
  }
  fuzz::FiniteSink sink;
  // Bit 1: the circles' chords (--chords), else their arcs.
  apt::to_canon(result.records, (bits & 1u) != 0 ? 25.4 : 1.0, sink,
                (bits & 2u) != 0 ? apt::Circles::Chords : apt::Circles::Arcs);
  sink.finish();
  return 0;
}
