// The diagnostic sink of the fuzz targets that run programs: every diagnostic
// is rendered (as `usina check` does) and then discarded, so the renderer's
// use of locations is fuzzed too.
#pragma once

#include <string>

#include "core/diagnostic.hpp"
#include "core/source.hpp"

namespace usina::fuzz {

class RenderAndDiscard final : public core::DiagnosticSink {
 public:
  explicit RenderAndDiscard(const core::SourceManager& sources) : sources_(sources) {}

  void report(core::Diagnostic d) override {
    const std::string text = core::render(d, sources_);
    (void)text;
  }

 private:
  const core::SourceManager& sources_;
};

}  // namespace usina::fuzz
