// Runs a program in the fanuc dialect and keeps what it wrote (shared by
// the fanuc tests).
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "gcode/dialect.hpp"
#include "romi_test_support.hpp"

namespace usina::gcode::fanuc_test {

using romi_test::Run;

inline std::unique_ptr<Run> run_fanuc(const std::string& text, InterpOptions opts = {},
                                      const std::vector<std::string>& options = {}) {
  return romi_test::run_in("fanuc", text, std::move(opts), options);
}

using romi_test::expect_near;

// The last move ends at `want`.
inline void expect_end(const Run& r, core::Vec3 want) {
  ASSERT_FALSE(r.ends().empty());
  expect_near(r.ends().back(), want);
}

}  // namespace usina::gcode::fanuc_test
