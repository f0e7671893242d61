#include "job/toml_reader.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "sim/profile_keys.hpp"

namespace usina::job {

LineStarts::LineStarts(std::string_view text) {
  starts_.push_back(0);
  for (std::size_t nl = text.find('\n'); nl != std::string_view::npos; nl = text.find('\n', nl + 1))
    starts_.push_back(nl + 1);
}

std::uint64_t LineStarts::offset(std::uint32_t line) const {
  if (line == 0) return 0;
  return starts_[std::min<std::size_t>(line, starts_.size()) - 1];
}

std::optional<toml::table> TomlReader::parse() {
  try {
    return toml::parse(text_);
  } catch (const toml::parse_error& e) {
    fail(e.source(), fmt::format("not valid TOML: {}", e.description()));
    return std::nullopt;
  }
}

core::SourceLoc TomlReader::loc(const toml::source_region& where) const {
  const auto line = static_cast<std::uint32_t>(where.begin.line);
  return {file_, line, static_cast<std::uint32_t>(where.begin.column), 1, lines_.offset(line)};
}

void TomlReader::report(core::Code code, const toml::source_region& where, std::string message,
                        core::Severity severity) {
  diags_.report({code, severity, loc(where), std::move(message)});
}

void TomlReader::fail(const toml::source_region& where, std::string message) {
  ok_ = false;
  report(code_, where, std::move(message));
}

void TomlReader::fail(core::Code code, const toml::source_region& where, std::string message) {
  ok_ = false;
  report(code, where, std::move(message));
}

std::optional<double> TomlReader::number(const toml::table& t, std::string_view what,
                                         const char* key, const Range& range, bool required) {
  const toml::node* n = t.get(key);
  if (n == nullptr) {
    if (required) fail(t.source(), fmt::format("{} needs the key '{}'", what, key));
    return std::nullopt;
  }
  const std::optional<double> v = n->value<double>();
  if (!v || !std::isfinite(*v) || n->is_boolean() || n->is_string()) {
    fail(n->source(), fmt::format("{} {} must be a number", what, key));
    return std::nullopt;
  }
  if (*v < range.min || *v > range.max) {
    fail(n->source(), fmt::format("{} {} = {:g} is out of range: give {:g} to {:g} {}", what, key,
                                  *v, range.min, range.max, range.unit));
    return std::nullopt;
  }
  return v;
}

std::optional<std::string> TomlReader::text(const toml::table& t, std::string_view what,
                                            const char* key, bool required) {
  const toml::node* n = t.get(key);
  if (n == nullptr) {
    if (required) fail(t.source(), fmt::format("{} needs the key '{}'", what, key));
    return std::nullopt;
  }
  if (!n->is_string()) {
    fail(n->source(), fmt::format("{} {} must be text (in quotes)", what, key));
    return std::nullopt;
  }
  return n->value<std::string>();
}

std::optional<bool> TomlReader::flag(const toml::table& t, std::string_view what, const char* key) {
  const toml::node* n = t.get(key);
  if (n == nullptr) return std::nullopt;
  if (!n->is_boolean()) {
    fail(n->source(), fmt::format("{} {} must be true or false", what, key));
    return std::nullopt;
  }
  return n->value<bool>();
}

std::optional<std::vector<double>> TomlReader::numbers(const toml::table& t, std::string_view what,
                                                       const char* key, std::size_t n,
                                                       const Range& range, bool required) {
  const toml::node* node = t.get(key);
  if (node == nullptr) {
    if (required) fail(t.source(), fmt::format("{} needs the key '{}'", what, key));
    return std::nullopt;
  }
  const toml::array* a = node->as_array();
  const std::string shape = n == 2 ? "[x, y]" : "[x, y, z]";
  if (a == nullptr || a->size() != n) {
    fail(node->source(), fmt::format("{} {} must be {} (numbers)", what, key, shape));
    return std::nullopt;
  }
  std::vector<double> out;
  for (const toml::node& e : *a) {
    const std::optional<double> v = e.value<double>();
    if (!v || e.is_boolean() || e.is_string() || !std::isfinite(*v) || *v < range.min ||
        *v > range.max) {
      fail(e.source(), fmt::format("{} {}: each number of {} must be from {:g} to {:g} {}", what,
                                   key, shape, range.min, range.max, range.unit));
      return std::nullopt;
    }
    out.push_back(*v);
  }
  return out;
}

const toml::table* TomlReader::section(const toml::table& root, const char* name,
                                       std::string_view file) {
  const toml::node* n = root.get(name);
  if (n == nullptr || !n->is_table()) {
    fail(n != nullptr ? n->source() : root.source(),
         fmt::format("{} needs a [{}] section", file, name));
    return nullptr;
  }
  return n->as_table();
}

const toml::array* TomlReader::entries(const toml::table& root, const char* name,
                                       std::string_view file) {
  const std::string_view keys[] = {name};
  known_keys(root, file, keys);
  const toml::node* n = root.get(name);
  if (n == nullptr || !n->is_array_of_tables() || n->as_array()->empty()) {
    fail(n != nullptr ? n->source() : root.source(),
         fmt::format("{} needs its [[{}]] entries", file, name));
    return nullptr;
  }
  return n->as_array();
}

void TomlReader::known_keys(const toml::table& t, std::string_view what,
                            std::span<const std::string_view> keys) {
  for (auto&& [key, node] : t) {
    const std::string_view name = key.str();
    if (std::find(keys.begin(), keys.end(), name) != keys.end()) continue;
    ok_ = false;
    const std::string_view near = sim::nearest_key(name, keys);
    std::string known;
    for (const std::string_view k : keys)
      known += fmt::format("{}{}", known.empty() ? "" : ", ", k);
    report(core::Code::UnknownJobKey, key.source(),
           fmt::format("unknown key `{}` in {}: {}", name, what,
                       near.empty() ? fmt::format("the keys here are {}", known)
                                    : fmt::format("did you mean `{}`?", near)));
  }
}

}  // namespace usina::job
