// Runs a program in the romi dialect (the romi tests; the runner of every
// dialect is support/dialect_run.hpp).
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "support/dialect_run.hpp"

namespace usina::gcode::romi_test {

using core::Vec3;
using dialect_test::expect_near;
using dialect_test::Run;
using dialect_test::run_in;

inline std::unique_ptr<Run> run_romi(const std::string& text, InterpOptions opts = {},
                                     const std::vector<std::string>& options = {}) {
  return run_in("romi", text, std::move(opts), options);
}

}  // namespace usina::gcode::romi_test
