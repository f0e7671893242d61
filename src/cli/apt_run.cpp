#include "cli/apt_run.hpp"

#include <cctype>
#include <string>

#include "apt/canon_out.hpp"
#include "apt/cl_text.hpp"
#include "apt/cldata.hpp"
#include "apt/processor.hpp"
#include "cli/run_guard.hpp"

namespace usina::cli {
namespace {

std::string extension_of(std::string_view file) {
  const std::size_t dot = file.rfind('.');
  const std::size_t slash = file.rfind('/');
  if (dot == std::string_view::npos || (slash != std::string_view::npos && slash > dot)) return "";
  std::string ext;
  for (const char c : file.substr(dot + 1))
    ext.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
  return ext;
}

}  // namespace

ProgramLanguage program_language(std::string_view from, std::string_view file) {
  const std::string_view name = from;
  if (name == "apt") return ProgramLanguage::Apt;
  if (name == "clsf") return ProgramLanguage::Clsf;
  if (name == "aptcl") return ProgramLanguage::AptCl;
  if (name == "cldata") return ProgramLanguage::Cldata;
  if (!from.empty()) return ProgramLanguage::Gcode;  // a G-code dialect's name
  const std::string ext = extension_of(file);
  if (ext == "apt") return ProgramLanguage::Apt;
  if (ext == "cls" || ext == "clsf") return ProgramLanguage::Clsf;
  if (ext == "ncl") return ProgramLanguage::AptCl;
  if (ext == "cldata") return ProgramLanguage::Cldata;
  return ProgramLanguage::Gcode;
}

int run_apt_program(const core::SourceManager& sources, std::uint32_t id, ProgramLanguage language,
                    double scale, canon::Sink& sink, DiagnosticPrinter& diags,
                    std::uint64_t max_ops) {
  RunGuard guard(sink, diags, max_ops);  // --max-ops and the progress line, as for G-code
  const std::string_view text = sources.get(id)->text();
  if (language == ProgramLanguage::Apt) {
    const apt::AptResult result = apt::process(text, id, guard.diags());
    apt::to_canon(result.records, scale, guard.sink());
    return diags.errors() == 0 ? 0 : 1;
  }
  // A CL file's records go to the canon stream as they are read.
  apt::ClToCanon canon(scale, guard.sink());
  const auto take = [&canon, &guard](apt::ClRecord&& r) {
    canon.record(r);
    return !guard.sink().stopped();
  };
  if (language == ProgramLanguage::Cldata) {
    apt::read_cldata(text, id, guard.diags(), take);
  } else {
    const apt::ClDialect dialect =
        language == ProgramLanguage::Clsf ? apt::ClDialect::Clsf : apt::ClDialect::AptCl;
    apt::read_cl_text(text, id, dialect, guard.diags(),
                      apt::ClConsumer{take, [&canon](double s) { canon.set_scale(s); }});
  }
  guard.sink().finish();
  return diags.errors() == 0 ? 0 : 1;
}

}  // namespace usina::cli
