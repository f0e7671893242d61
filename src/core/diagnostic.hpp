// Diagnostics are data: a stable code, a severity, a source location and a
// message; rendered once, like a compiler's (file:line:col, the line, a caret).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "core/diagnostic_codes.hpp"

namespace usina::core {

enum class Code : std::uint16_t {
#define USINA_X(name, id) name,
  USINA_DIAGNOSTIC_CODES(USINA_X)
#undef USINA_X
};

// The stable name of a code, e.g. "E_ARC_RADIUS_MISMATCH".
std::string_view code_name(Code code);

enum class Severity : std::uint8_t { Note, Warning, Error };

std::string_view severity_name(Severity s);

// Where in which source a thing is. Lines and columns are 1-based; 0 means
// "unknown". `line_offset` is the byte offset of the line's start, so the
// line can be shown without keeping the text.
struct SourceLoc {
  std::uint32_t file = 0;
  std::uint32_t line = 0;
  std::uint32_t col = 0;
  std::uint32_t length = 0;
  std::uint64_t line_offset = 0;
};

struct Diagnostic {
  Code code = Code::Unsupported;
  Severity severity = Severity::Error;
  SourceLoc loc;
  std::string message;
};

class DiagnosticSink {
 public:
  virtual ~DiagnosticSink() = default;
  virtual void report(Diagnostic d) = 0;
};

// Keeps every diagnostic, counts errors.
class DiagnosticList final : public DiagnosticSink {
 public:
  void report(Diagnostic d) override;

  const std::vector<Diagnostic>& all() const { return items_; }

  int error_count() const { return errors_; }

  bool has_errors() const { return errors_ > 0; }

  void clear();

 private:
  std::vector<Diagnostic> items_;
  int errors_ = 0;
};

// Counts the errors and keeps nothing: for a run whose diagnostics are
// another's to show (the web viewer shows what ran; the check says why).
class ErrorCount final : public DiagnosticSink {
 public:
  void report(Diagnostic d) override {
    if (d.severity == Severity::Error) ++errors_;
  }

  std::uint64_t errors() const { return errors_; }

 private:
  std::uint64_t errors_ = 0;
};

}  // namespace usina::core
