// Runs a program in a dialect by name, as the usina command does, and keeps
// the ops and diagnostics it wrote (the gcode tests of every dialect).
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "canon/toolpath.hpp"
#include "canon/trace_json.hpp"
#include "core/source.hpp"
#include "gcode/dialect.hpp"

namespace usina::gcode::dialect_test {

using core::Vec3;

struct Run {
  core::SourceManager sources;
  core::DiagnosticList diags;
  canon::Toolpath path;
  bool ok = false;

  template <typename T>
  std::vector<T> all() const {
    std::vector<T> out;
    for (const canon::Op& op : path.ops()) {
      if (const T* t = std::get_if<T>(&op.kind)) out.push_back(*t);
    }
    return out;
  }

  // End points of every move, in order.
  std::vector<Vec3> ends() const {
    std::vector<Vec3> out;
    for (const canon::Op& op : path.ops()) {
      if (const auto* t = std::get_if<canon::Traverse>(&op.kind)) out.push_back(t->to);
      if (const auto* f = std::get_if<canon::Feed>(&op.kind)) out.push_back(f->to);
      if (const auto* a = std::get_if<canon::Arc>(&op.kind)) out.push_back(a->to);
    }
    return out;
  }

  bool has(core::Code code) const {
    for (const core::Diagnostic& d : diags.all()) {
      if (d.code == code) return true;
    }
    return false;
  }

  // The first error's code, or Message when none.
  core::Code first_error() const {
    for (const core::Diagnostic& d : diags.all()) {
      if (d.severity == core::Severity::Error) return d.code;
    }
    return core::Code::Message;
  }

  std::string first_error_text() const {
    for (const core::Diagnostic& d : diags.all()) {
      if (d.severity == core::Severity::Error) return d.message;
    }
    return {};
  }
};

// `text` run by the dialect `name` with `options` (NAME=VALUE); the fanuc
// tests use it too.
inline std::unique_ptr<Run> run_in(const char* name, const std::string& text,
                                   InterpOptions opts = {},
                                   const std::vector<std::string>& options = {}) {
  auto r = std::make_unique<Run>();
  const std::uint32_t id = r->sources.add(core::SourceFile::from_string("test.nc", text));
  const Dialect* d = find_dialect(name);
  EXPECT_NE(d, nullptr);
  auto resolved = resolve_options(*d, options);
  EXPECT_TRUE(resolved) << resolved.error();
  OptionValues values = resolved.value_or(OptionValues{});
  auto runner =
      d->make_runner(RunContext{r->sources, std::move(opts), std::move(values), r->path, r->diags});
  r->ok = runner->run(id);
  return r;
}

// What a run wrote, as text to compare two runs by: its operations as JSON
// lines, its diagnostics (line:col: message), whether it succeeded, the
// modes it ended in (what a restart from there starts with). With
// `whole_road`, every block takes the dialect's whole road, past its
// plain-move shortcut (a key the command line refuses) and past the
// interpreter's (InterpOptions::plain_move_shortcut).
inline std::string run_outcome(const char* name, const std::string& text, bool whole_road) {
  Run r;
  const std::uint32_t id = r.sources.add(core::SourceFile::from_string("p.nc", text));
  const Dialect* d = find_dialect(name);
  EXPECT_NE(d, nullptr);
  OptionValues values = default_options(*d);
  if (whole_road) values["whole_road"] = "1";
  InterpOptions opts;
  opts.plain_move_shortcut = !whole_road;
  auto runner =
      d->make_runner(RunContext{r.sources, std::move(opts), std::move(values), r.path, r.diags});
  r.ok = runner->run(id);
  fmt::memory_buffer out;
  for (const canon::Op& op : r.path.ops()) {
    canon::append_jsonl(out, op);
    out.push_back('\n');
  }
  for (const core::Diagnostic& diag : r.diags.all())
    fmt::format_to(fmt::appender(out), "{}:{}: {}\n", diag.loc.line, diag.loc.col, diag.message);
  if (const std::optional<RunModes> m = runner->modes()) {
    fmt::format_to(fmt::appender(out), "modes inch {} G{} incremental {} motion {} moved {}\n",
                   m->inch, m->plane, m->incremental, m->motion, m->frame_moved);
  }
  fmt::format_to(fmt::appender(out), "ok {}\n", r.ok);
  return fmt::to_string(out);
}

// The programs `program(seed)` for seeds 0 to count - 1, each run with the
// dialect's plain-move shortcut and down the whole road: the same outcome
// expected. Returns how many ran to their end.
template <typename Program>
int expect_shortcut_agrees(const char* name, Program program, unsigned count) {
  int finished = 0;
  for (unsigned seed = 0; seed < count; ++seed) {
    const std::string text = program(seed);
    const std::string shortcut = run_outcome(name, text, false);
    EXPECT_EQ(shortcut, run_outcome(name, text, true)) << "seed " << seed << "\n" << text;
    if (testing::Test::HasFailure()) break;
    finished += shortcut.ends_with("ok true\n") ? 1 : 0;
  }
  return finished;
}

inline void expect_near(const Vec3& got, const Vec3& want, double tol = 1e-6) {
  EXPECT_NEAR(got.x, want.x, tol) << "x";
  EXPECT_NEAR(got.y, want.y, tol) << "y";
  EXPECT_NEAR(got.z, want.z, tol) << "z";
}

}  // namespace usina::gcode::dialect_test
