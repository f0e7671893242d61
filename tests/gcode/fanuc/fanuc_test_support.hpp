// Runs a program in the fanuc dialect and keeps what it wrote (shared by
// the fanuc tests).
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "gcode/dialect.hpp"
#include "support/dialect_run.hpp"

namespace usina::gcode::fanuc_test {

using dialect_test::Run;

inline std::unique_ptr<Run> run_fanuc(const std::string& text, InterpOptions opts = {},
                                      const std::vector<std::string>& options = {}) {
  return dialect_test::run_in("fanuc", text, std::move(opts), options);
}

// `text` with the offset page `path` (usina's --offsets): the fanuc
// dialect's own input, handed to it with its options.
inline std::unique_ptr<Run> run_fanuc_offsets(const std::string& text, const std::string& path) {
  auto r = std::make_unique<Run>();
  const std::uint32_t id = r->sources.add(core::SourceFile::from_string("test.nc", text));
  const Dialect* d = find_dialect("fanuc");
  OptionValues values = default_options(*d);
  values["offsets"] = path;
  auto runner =
      d->make_runner(RunContext{r->sources, InterpOptions{}, std::move(values), r->path, r->diags});
  r->ok = runner->run(id);
  return r;
}

using dialect_test::expect_near;

// The last move ends at `want`.
inline void expect_end(const Run& r, core::Vec3 want) {
  ASSERT_FALSE(r.ends().empty());
  expect_near(r.ends().back(), want);
}

}  // namespace usina::gcode::fanuc_test
