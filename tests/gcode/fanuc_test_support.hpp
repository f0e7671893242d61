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

// A point within 1e-6 mm of `want`, axis by axis.
inline void expect_near(core::Vec3 got, core::Vec3 want) {
  EXPECT_NEAR(got.x, want.x, 1e-6);
  EXPECT_NEAR(got.y, want.y, 1e-6);
  EXPECT_NEAR(got.z, want.z, 1e-6);
}

// The last move ends at `want`.
inline void expect_end(const Run& r, core::Vec3 want) {
  ASSERT_FALSE(r.ends().empty());
  expect_near(r.ends().back(), want);
}

}  // namespace usina::gcode::fanuc_test
