// Runs a program in the fanuc dialect and keeps what it wrote (shared by
// the fanuc tests).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "gcode/dialect.hpp"
#include "romi_test_support.hpp"

namespace usina::gcode::fanuc_test {

using romi_test::Run;

inline std::unique_ptr<Run> run_fanuc(const std::string& text, InterpOptions opts = {},
                                      const std::vector<std::string>& options = {}) {
  auto r = std::make_unique<Run>();
  const std::uint32_t id = r->sources.add(core::SourceFile::from_string("test.nc", text));
  const Dialect* d = find_dialect("fanuc");
  EXPECT_NE(d, nullptr);
  OptionValues values;
  EXPECT_FALSE(resolve_options(*d, options, values).has_value());
  auto runner =
      d->make_runner(RunContext{r->sources, std::move(opts), std::move(values), r->path, r->diags});
  r->ok = runner->run(id);
  return r;
}

}  // namespace usina::gcode::fanuc_test
