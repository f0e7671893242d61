// Old spellings of options kept for one release (docs/gen.md, "Names"): an
// old name sets the same value as the new one, is hidden from --help, and
// says once on standard error that it is deprecated.
#pragma once

#include <cstdio>
#include <string>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "core/diagnostic.hpp"

namespace usina::cli {

inline void warn_deprecated(const std::string& old_name, const std::string& new_name) {
  fmt::print(stderr,
             "usina: warning: {} is deprecated; use {} (the old name will be removed in the next "
             "release) [{}]\n",
             old_name, new_name, core::code_name(core::Code::DeprecatedOption));
}

// Adds `old_name` as a hidden option storing into `value`, as `canonical`
// does; giving both is a usage error. (Not CLI11's excludes(): it would
// print an empty "Excludes:" in the canonical option's help.)
template <class T>
CLI::Option* add_deprecated_option(CLI::App& cmd, const std::string& old_name,
                                   CLI::Option* canonical, T& value) {
  const std::string new_name = canonical->get_name();
  CLI::Validator warn(
      [old_name, new_name, canonical](std::string&) {
        // Runs once the whole command line is read, so the count is known.
        if (canonical->count() > 0) {
          return fmt::format("{} is the old name of {}: give one of them", old_name, new_name);
        }
        warn_deprecated(old_name, new_name);
        return std::string();
      },
      "");
  warn.application_index(0);  // once, not for each value
  CLI::Option* old = cmd.add_option(old_name, value, "deprecated: " + new_name);
  old->group("")->check(warn);
  return old;
}

}  // namespace usina::cli
