// What the job's three TOML files (the job, the tool library, the materials)
// share: every problem a diagnostic at the line and column of its key (toml++
// gives each node its source region), the typed reads of a key, and the
// check that a table has no key usina does not read: a job's keys set what
// is cut, so a misspelt one is an error with the nearest valid name, never a
// value silently left at its default.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "core/diagnostic.hpp"

namespace usina::job {

// Where each line of a text starts (for a SourceLoc's line_offset, so a
// diagnostic shows its line), found once: a file with a diagnostic on each
// of its 50,000 lines must not scan its text 50,000 times (the fuzz target
// found that).
class LineStarts {
 public:
  explicit LineStarts(std::string_view text);
  // The byte offset of the start of 1-based `line` (the last line's start
  // past the end).
  std::uint64_t offset(std::uint32_t line) const;

 private:
  std::vector<std::uint64_t> starts_;
};

// A closed range a number must be in; `what` names its unit in messages.
struct Range {
  double min;
  double max;
  const char* unit;
};

class TomlReader {
 public:
  // `text` is the whole file (kept to locate lines); `code` is the file's
  // general error (E_BAD_JOB, E_BAD_TOOL_LIBRARY, E_BAD_MATERIALS).
  TomlReader(std::string_view text, std::uint32_t file, core::Code code,
             core::DiagnosticSink& diags)
      : text_(text), lines_(text), file_(file), code_(code), diags_(diags) {}

  // The parsed file, or nullopt after reporting where it is not TOML.
  std::optional<toml::table> parse();

  core::SourceLoc loc(const toml::source_region& where) const;
  void report(core::Code code, const toml::source_region& where, std::string message,
              core::Severity severity = core::Severity::Error);
  // An error of the file's own code; ok() turns false.
  void fail(const toml::source_region& where, std::string message);
  // The same with a code of its own (an unknown operation ...).
  void fail(core::Code code, const toml::source_region& where, std::string message);

  // Typed reads: nullopt when the key is absent (an error when `required`)
  // or after reporting a wrong type or range. `what` names the table.
  std::optional<double> number(const toml::table& t, std::string_view what, const char* key,
                               const Range& range, bool required);
  std::optional<std::string> text(const toml::table& t, std::string_view what, const char* key,
                                  bool required);
  // true or false; nullopt when absent or after reporting another type.
  std::optional<bool> flag(const toml::table& t, std::string_view what, const char* key);
  // [x, y] (or [x, y, z] with n = 3) of numbers within `range`.
  std::optional<std::vector<double>> numbers(const toml::table& t, std::string_view what,
                                             const char* key, std::size_t n, const Range& range,
                                             bool required);

  // The section [name] of `root`; null (an error) when absent or not a table.
  const toml::table* section(const toml::table& root, const char* name, std::string_view file);
  // The file's [[name]] entries, after checking `root` has no other key;
  // null (an error) when there are none.
  const toml::array* entries(const toml::table& root, const char* name, std::string_view file);

  // E_UNKNOWN_JOB_KEY for each key of `t` not in `keys`.
  void known_keys(const toml::table& t, std::string_view what,
                  std::span<const std::string_view> keys);

  bool ok() const { return ok_; }

 private:
  std::string_view text_;
  LineStarts lines_;
  std::uint32_t file_;
  core::Code code_;
  core::DiagnosticSink& diags_;
  bool ok_ = true;
};

}  // namespace usina::job
