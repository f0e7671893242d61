// What the grbl dialect's tests share: a program run through the dialect,
// with its Grbl error numbers, diagnostics and moves at hand.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "canon/toolpath.hpp"
#include "core/source.hpp"
#include "gcode/dialect.hpp"

namespace usina::gcode::testing {

struct GrblRun {
  core::SourceManager sources;
  core::DiagnosticList diags;
  canon::Toolpath path;
  bool ok = false;

  // (line, Grbl number) of every E_GRBL, in order.
  std::vector<std::pair<std::uint32_t, int>> errors() const {
    std::vector<std::pair<std::uint32_t, int>> out;
    for (const core::Diagnostic& d : diags.all()) {
      if (d.code != core::Code::GrblError) continue;
      const std::size_t at = d.message.find("error:");
      out.emplace_back(d.loc.line, std::stoi(d.message.substr(at + 6)));
    }
    return out;
  }

  std::vector<const core::Diagnostic*> with(core::Code c) const {
    std::vector<const core::Diagnostic*> out;
    for (const core::Diagnostic& d : diags.all())
      if (d.code == c) out.push_back(&d);
    return out;
  }

  bool has(core::Code c) const { return !with(c).empty(); }

  // (op name, end point) of every move.
  std::vector<std::pair<std::string, core::Vec3>> moves() const {
    std::vector<std::pair<std::string, core::Vec3>> out;
    for (const canon::Op& op : path.ops()) {
      if (!canon::is_motion(op.kind)) continue;
      core::Vec3 to;
      std::visit(
          [&](const auto& o) {
            if constexpr (requires { o.to; }) to = o.to;
          },
          op.kind);
      out.emplace_back(canon::op_name(op.kind), to);
    }
    return out;
  }
};

// `text` run by the grbl dialect with `opts` (NAME=VALUE dialect options).
inline std::unique_ptr<GrblRun> run_grbl(const std::string& text,
                                         const std::vector<std::string>& opts = {}) {
  auto r = std::make_unique<GrblRun>();
  const std::uint32_t id = r->sources.add(core::SourceFile::from_string("t.nc", text));
  const Dialect* d = find_dialect("grbl");
  EXPECT_NE(d, nullptr);
  auto resolved = resolve_options(*d, opts);
  EXPECT_TRUE(resolved) << resolved.error();
  OptionValues values = resolved.value_or(OptionValues{});
  auto runner = d->make_runner(RunContext{r->sources, {}, std::move(values), r->path, r->diags});
  r->ok = runner->run(id);
  return r;
}

}  // namespace usina::gcode::testing
