// Test helpers: canon through a post into text, text back through usina's
// own interpreter, and a comparison of the two tool paths.
#pragma once

#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "canon/toolpath.hpp"
#include "core/source.hpp"
#include "gcode/dialect.hpp"
#include "gcode/interp/interpreter.hpp"
#include "post/post.hpp"

namespace usina::test {

// The program `post` writes for `ops`; diagnostics into `diags`.
inline std::string post_text(const std::vector<canon::Op>& ops, const std::string& post,
                             core::DiagnosticList& diags, const post::PostOptions& opts = {}) {
  std::ostringstream out;
  auto sink = post::make_post(post, out, opts, diags);
  EXPECT_NE(sink, nullptr);
  if (!sink) return {};
  for (const canon::Op& op : ops)
    sink->on(op);
  sink->finish();
  return out.str();
}

// The ops usina's rs274ngc interpreter makes of `text`; errors fail the test.
inline std::vector<canon::Op> interpret(const std::string& text) {
  core::SourceManager sources;
  const std::uint32_t id = sources.add(core::SourceFile::from_string("post.ngc", text));
  core::DiagnosticList diags;
  canon::Toolpath path;
  gcode::Interpreter interp(sources, gcode::InterpOptions{}, path, diags);
  EXPECT_TRUE(interp.run(id));
  for (const core::Diagnostic& d : diags.all())
    EXPECT_NE(d.severity, core::Severity::Error) << core::render(d, sources);
  return path.ops();
}

// The ops usina makes of `text` read in `dialect` (the control a post wrote
// for), or nullopt when usina does not read that dialect yet; errors fail
// the test.
inline std::optional<std::vector<canon::Op>> interpret_in(const std::string& text,
                                                          const std::string& dialect) {
  const gcode::Dialect* d = gcode::find_dialect(dialect);
  if (d == nullptr) return std::nullopt;
  core::SourceManager sources;
  const std::uint32_t id = sources.add(core::SourceFile::from_string("post.nc", text));
  core::DiagnosticList diags;
  canon::Toolpath path;
  const gcode::OptionValues options = gcode::default_options(*d);
  auto runner =
      d->make_runner(gcode::RunContext{sources, gcode::InterpOptions{}, options, path, diags});
  EXPECT_TRUE(runner->run(id)) << dialect;
  for (const core::Diagnostic& dg : diags.all())
    EXPECT_NE(dg.severity, core::Severity::Error) << dialect << ": " << core::render(dg, sources);
  return path.ops();
}

// Where each motion op ends, consecutive duplicates (a move the post could
// not write because it rounds to no change) dropped.
inline std::vector<core::Vec3> motion_ends(const std::vector<canon::Op>& ops, double tol) {
  std::vector<core::Vec3> out;
  for (const canon::Op& op : ops) {
    core::Vec3 to;
    if (const auto* t = std::get_if<canon::Traverse>(&op.kind)) {
      to = t->to;
    } else if (const auto* f = std::get_if<canon::Feed>(&op.kind)) {
      to = f->to;
    } else if (const auto* a = std::get_if<canon::Arc>(&op.kind)) {
      to = a->to;
    } else {
      continue;
    }
    if (!out.empty() && core::distance(out.back(), to) < tol) continue;
    out.push_back(to);
  }
  return out;
}

inline void expect_same_path(const std::vector<canon::Op>& a, const std::vector<canon::Op>& b,
                             double tol) {
  const auto pa = motion_ends(a, tol);
  const auto pb = motion_ends(b, tol);
  ASSERT_EQ(pa.size(), pb.size());
  for (std::size_t i = 0; i < pa.size(); ++i)
    ASSERT_LT(core::distance(pa[i], pb[i]), tol)
        << "move " << i << ": (" << pa[i].x << ", " << pa[i].y << ", " << pa[i].z << ") vs ("
        << pb[i].x << ", " << pb[i].y << ", " << pb[i].z << ")";
}

inline canon::Op op(canon::OpKind k, canon::Origin origin = canon::Origin::Program) {
  return canon::Op{std::move(k), {}, origin};
}

}  // namespace usina::test
