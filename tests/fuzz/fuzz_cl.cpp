// libFuzzer target for the CL readers (issue 15): the first byte picks the
// reader by its value mod 3 (0 NX CLSF, 1 APT CL, 2 binary CLDATA), the rest
// is the file. Every record read goes to the canon stream (trapping on a
// number that is not finite), then all of them are written as CLDATA and ISO
// 4343; the CLDATA read back must give the same record print. Every
// diagnostic is rendered and discarded. Any input must give records or
// diagnostics, never a crash, a hang or a broken round trip.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <variant>

#include "apt/canon_out.hpp"
#include "apt/cl_text.hpp"
#include "apt/cldata.hpp"
#include "apt/iso4343.hpp"
#include "canon/sink.hpp"
#include "core/source.hpp"
#include "finite_sink.hpp"
#include "render_and_discard.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace usina;
  if (size == 0) return 0;
  const int reader = data[0] % 3;
  core::SourceManager sources;
  fuzz::RenderAndDiscard diags(sources);
  std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  const std::uint32_t id = sources.add(core::SourceFile::from_string("<fuzz>", std::move(text)));
  const std::string_view file = sources.get(id)->text();
  std::vector<apt::ClRecord> records;
  fuzz::FiniteSink sink;
  apt::ClToCanon canon(1.0, sink);
  const auto take = [&](apt::ClRecord&& r) {
    canon.record(r);
    records.push_back(std::move(r));
    return true;
  };
  if (reader == 2) {
    apt::read_cldata(file, id, diags, take);
  } else {
    const apt::ClDialect d = reader == 0 ? apt::ClDialect::Clsf : apt::ClDialect::AptCl;
    apt::read_cl_text(file, id, d, diags,
                      apt::ClConsumer{take, [&canon](double s) { canon.set_scale(s); }});
  }
  sink.finish();
  const std::string bytes = apt::write_cldata(records);
  core::DiagnosticList again;
  const std::vector<apt::ClRecord> back = apt::read_cldata(bytes, id, again);
  // What the writer wrote reads back whole, as the same records.
  if (again.has_errors() || apt::record_print(back) != apt::record_print(records)) __builtin_trap();
  (void)apt::write_iso4343(records, "MM");
  return 0;
}
