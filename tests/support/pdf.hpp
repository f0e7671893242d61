// What the tests read of a PDF: its pages, counted in its objects (cairo
// writes each page as a plain `/Type /Page` dictionary, no object
// streams), and its text through poppler's pdftotext (poppler-utils,
// scripts/setup.sh), which a test without it skips.
#pragma once

#include <optional>
#include <string>

#include "support/files.hpp"
#include "support/usina_process.hpp"

namespace usina::test {

inline std::size_t pdf_pages(const std::string& bytes) {
  return count(bytes, "/Type /Page") - count(bytes, "/Type /Pages");
}

inline bool have_pdftotext() {
  return std::system("command -v pdftotext >/dev/null 2>&1") == 0;
}

// The PDF's text in reading order, nullopt when pdftotext is missing or fails.
inline std::optional<std::string> pdf_text(const std::string& path) {
  if (!have_pdftotext()) return std::nullopt;
  const TempDir dir;
  const Run r = shell("pdftotext -layout " + quote(path) + " -", dir.path("err"));
  if (r.status != 0) return std::nullopt;
  return r.out;
}

}  // namespace usina::test
