// Validators CLI11 lacks, shared by the verbs' options.
#pragma once

#include <cmath>
#include <cstdlib>
#include <string>

#include <CLI/CLI.hpp>

namespace usina::cli {

// CLI11's ranges let NaN through (every comparison with it is false) and its
// PositiveNumber lets infinity through: a number usina computes with must be
// finite.
inline const CLI::Validator kFinite(
    [](std::string& text) {
      const double v = std::strtod(text.c_str(), nullptr);
      return std::isfinite(v) ? std::string() : "not a finite number: " + text;
    },
    "FINITE");

// A finite number above zero (a length, a depth).
inline const CLI::Validator kPositiveFinite(
    [](std::string& text) {
      const double v = std::strtod(text.c_str(), nullptr);
      return std::isfinite(v) && v > 0.0 ? std::string()
                                         : "not a finite number above zero: " + text;
    },
    "POSITIVE");

}  // namespace usina::cli
