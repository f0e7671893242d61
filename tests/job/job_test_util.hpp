// Helpers for the job tests: a job file written to a scratch folder around
// the repository's example tool library, materials and drawing, and loaded.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "core/diagnostic.hpp"
#include "core/source.hpp"
#include "job/load.hpp"
#include "support/files.hpp"

namespace usina::job::testing {

inline std::string repo(const std::string& rel) {
  return std::string(USINA_TEST_DIR) + "/../" + rel;
}

// job_text's own lines come first: the operations start on line 10.
constexpr std::uint32_t kFirstOpLine = 10;

// A [job] and [stock] of the plate example, absolute paths, then `ops`
// (the [[operation]] entries) and `extra_stock` lines in [stock].
inline std::string job_text(const std::string& ops,
                            const std::string& material = "aluminium-wrought") {
  return "[job]\n"
         "name = \"test\"\n"
         "tools = \"" +
         repo("examples/tools/shop.toml") +
         "\"\n"
         "materials = \"" +
         repo("data/materials.toml") +
         "\"\n"
         "drawing = \"" +
         repo("examples/jobs/plate.dxf") +
         "\"\n"
         "[stock]\n"
         "shape = \"box\"\n"
         "size = [130.0, 90.0, 10.0]\n"
         "material = \"" +
         material + "\"\n" + ops;
}

struct Loaded {
  core::SourceManager sources;
  core::DiagnosticList diags;
  std::optional<LoadedJob> job;
  std::string io_error;
};

inline std::unique_ptr<Loaded> load_text(const std::string& text) {
  auto l = std::make_unique<Loaded>();
  const test::TempDir dir;
  l->job = load_job(dir.write("job.toml", text), l->sources, l->diags, l->io_error);
  return l;
}

// The first diagnostic of `code`, or null.
inline const core::Diagnostic* find(const core::DiagnosticList& d, core::Code code) {
  for (const core::Diagnostic& x : d.all()) {
    if (x.code == code) return &x;
  }
  return nullptr;
}

}  // namespace usina::job::testing
