// What the interpreter tests share (tests/gcode/interp/, rs274ngc/): a run of
// the RS274NGC interpreter over a small program, with the ops, the
// parameters and the diagnostics it wrote, and checks on them.
#pragma once

#include <stdlib.h>
#include <unistd.h>

#include <cmath>
#include <fstream>
#include <memory>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include "canon/toolpath.hpp"
#include "core/source.hpp"
#include "core/units.hpp"
#include "gcode/interp/interpreter.hpp"
#include "support/files.hpp"

namespace usina::gcode::interp_test {

using canon::Arc;
using canon::Feed;
using canon::Traverse;
using core::Code;
using core::Vec3;

constexpr double kTol = 1e-9;
constexpr double kInch = core::kMmPerInch;

// End points of every motion op of `path`, in order.
inline std::vector<Vec3> motion_ends(const canon::Toolpath& path) {
  std::vector<Vec3> out;
  for (const canon::Op& op : path.ops()) {
    if (const auto* t = std::get_if<Traverse>(&op.kind)) out.push_back(t->to);
    if (const auto* f = std::get_if<Feed>(&op.kind)) out.push_back(f->to);
    if (const auto* a = std::get_if<Arc>(&op.kind)) out.push_back(a->to);
    if (const auto* p = std::get_if<canon::Probe>(&op.kind)) out.push_back(p->to);
    if (const auto* s = std::get_if<canon::Spline>(&op.kind)) out.push_back(s->to);
  }
  return out;
}

// One run of the interpreter over a program, with everything it wrote.
struct Run {
  core::SourceManager sources;
  core::DiagnosticList diags;
  canon::Toolpath path;
  std::unique_ptr<Interpreter> interp;
  bool ok = false;

  const std::vector<canon::Op>& ops() const { return path.ops(); }

  template <typename T>
  std::vector<T> all() const {
    std::vector<T> out;
    for (const canon::Op& op : path.ops()) {
      if (const T* t = std::get_if<T>(&op.kind)) out.push_back(*t);
    }
    return out;
  }

  // Ops of kind T with the location of the block that made them.
  template <typename T>
  std::vector<const canon::Op*> ops_of() const {
    std::vector<const canon::Op*> out;
    for (const canon::Op& op : path.ops()) {
      if (std::holds_alternative<T>(op.kind)) out.push_back(&op);
    }
    return out;
  }

  // End points of every motion op, in order.
  std::vector<Vec3> ends() const { return motion_ends(path); }

  // The names of the ops, in order ("traverse feed end").
  std::string kinds() const {
    std::string out;
    for (const canon::Op& op : path.ops()) {
      if (!out.empty()) out += ' ';
      out += canon::op_name(op.kind);
    }
    return out;
  }

  std::vector<core::Diagnostic> of_severity(core::Severity s) const {
    std::vector<core::Diagnostic> out;
    for (const core::Diagnostic& d : diags.all()) {
      if (d.severity == s) out.push_back(d);
    }
    return out;
  }

  double param(int index) const { return interp->parameters().get(index); }

  bool has(core::Code code) const {
    for (const core::Diagnostic& d : diags.all()) {
      if (d.code == code) return true;
    }
    return false;
  }

  // The first diagnostic's message, for a failed assertion's text.
  std::string first_error() const {
    return diags.all().empty() ? std::string("(no diagnostic)") : diags.all()[0].message;
  }
};

inline std::unique_ptr<Run> run(const std::string& text, InterpOptions opts = {},
                                const std::vector<std::pair<int, double>>& params = {}) {
  auto r = std::make_unique<Run>();
  const std::uint32_t id = r->sources.add(core::SourceFile::from_string("test.ngc", text));
  r->interp = std::make_unique<Interpreter>(r->sources, std::move(opts), r->path, r->diags);
  for (const auto& [index, value] : params)
    r->interp->set_parameter(index, value);
  r->ok = r->interp->run(id);
  return r;
}

inline std::string show(const Vec3& v) {
  return fmt::format("({}, {}, {})", v.x, v.y, v.z);
}

#define EXPECT_VEC(actual, ...)                                                     \
  do {                                                                              \
    const Vec3 a_ = (actual);                                                       \
    const Vec3 e_{__VA_ARGS__};                                                     \
    EXPECT_TRUE(std::fabs(a_.x - e_.x) <= kTol && std::fabs(a_.y - e_.y) <= kTol && \
                std::fabs(a_.z - e_.z) <= kTol)                                     \
        << "actual " << show(a_) << ", expected " << show(e_);                      \
  } while (0)

// Runs `text`, which must succeed.
#define RUN_OK(r, ...)                                                           \
  auto r = run(__VA_ARGS__);                                                     \
  ASSERT_TRUE(r->ok) << (r->diags.all().empty() ? std::string("(no diagnostic)") \
                                                : r->diags.all()[0].message);    \
  ASSERT_EQ(r->diags.error_count(), 0)

// The run's first error must be `code` at `line`:`col`.
inline void expect_error(const Run& r, Code code, std::uint32_t line, std::uint32_t col) {
  EXPECT_FALSE(r.ok);
  const auto errors = r.of_severity(core::Severity::Error);
  ASSERT_EQ(errors.size(), 1u) << "expected exactly one error";
  const core::Diagnostic& d = errors[0];
  EXPECT_EQ(core::code_name(d.code), core::code_name(code)) << d.message;
  EXPECT_EQ(d.loc.line, line) << d.message;
  EXPECT_EQ(d.loc.col, col) << d.message;
  EXPECT_FALSE(d.message.empty());
}

// A program that must stop at one error: `code` at `line`:`col`.
struct ErrorCase {
  const char* what;  // the rule the row checks
  const char* program;
  Code code;
  std::uint32_t line;
  std::uint32_t col;
  bool with_tools = false;  // run with tools() in the table
};

inline InterpOptions with_tools();

template <std::size_t N>
inline void expect_errors(const ErrorCase (&cases)[N]) {
  for (const ErrorCase& c : cases) {
    SCOPED_TRACE(std::string(c.what) + ": " + c.program);
    auto r = run(c.program, c.with_tools ? with_tools() : InterpOptions{});
    expect_error(*r, c.code, c.line, c.col);
  }
}

inline ToolTable tools() {
  ToolTable t;
  ToolEntry one;
  one.number = 1;
  one.offset = {0, 0, 10};
  one.diameter = 6;
  t.set(one);
  ToolEntry two;
  two.number = 2;
  two.offset = {0, 0, 25};
  two.diameter = 12.7;
  t.set(two);
  return t;
}

inline InterpOptions with_tools() {
  InterpOptions o;
  o.tools = tools();
  return o;
}

using test::TempDir;

}  // namespace usina::gcode::interp_test
