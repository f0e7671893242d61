#include "cli/apt_run.hpp"

#include <cctype>

#include "apt/canon_out.hpp"
#include "apt/processor.hpp"
#include "cli/run_guard.hpp"

namespace usina::cli {

bool is_apt_file(std::string_view file) {
  if (file.size() < 4) return false;
  const std::string_view ext = file.substr(file.size() - 4);
  return ext[0] == '.' && std::tolower(static_cast<unsigned char>(ext[1])) == 'a' &&
         std::tolower(static_cast<unsigned char>(ext[2])) == 'p' &&
         std::tolower(static_cast<unsigned char>(ext[3])) == 't';
}

int run_apt_program(const core::SourceManager& sources, std::uint32_t id, double scale,
                    canon::Sink& sink, DiagnosticPrinter& diags, std::uint64_t max_ops) {
  RunGuard guard(sink, diags, max_ops);  // --max-ops and the progress line, as for G-code
  const apt::AptResult result = apt::process(sources.get(id)->text(), id, guard.diags());
  apt::to_canon(result.records, scale, guard.sink());
  return diags.errors() == 0 ? 0 : 1;
}

}  // namespace usina::cli
