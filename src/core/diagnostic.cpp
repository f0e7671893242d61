#include "core/diagnostic.hpp"

#include <array>

namespace usina::core {

std::string_view code_name(Code code) {
  static constexpr std::array kNames = {
#define USINA_X(name, id) std::string_view(#id),
      USINA_DIAGNOSTIC_CODES(USINA_X)
#undef USINA_X
  };
  return kNames.at(static_cast<std::size_t>(code));
}

std::string_view severity_name(Severity s) {
  switch (s) {
  case Severity::Note: return "note";
  case Severity::Warning: return "warning";
  case Severity::Error: return "error";
  }
  return "error";
}

void DiagnosticList::report(Diagnostic d) {
  if (d.severity == Severity::Error) ++errors_;
  items_.push_back(std::move(d));
}

void DiagnosticList::clear() {
  items_.clear();
  errors_ = 0;
}

}  // namespace usina::core
