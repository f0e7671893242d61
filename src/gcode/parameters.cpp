#include "gcode/parameters.hpp"

#include <algorithm>
#include <cctype>

namespace usina::gcode {

std::string normalise_name(std::string_view raw) {
  std::string out;
  out.reserve(raw.size());
  for (const char c : raw) {
    if (c == ' ' || c == '\t') continue;
    out.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
  }
  return out;
}

std::optional<double> Parameters::named(std::string_view name) const {
  // RS274NGC: a name starting with '_' is global, any other is local.
  if (!name.empty() && name.front() == '_') {
    auto it = globals_.find(std::string(name));
    if (it != globals_.end()) return it->second;
    return std::nullopt;
  }
  const Scope& local = locals_.back();
  auto it = local.find(std::string(name));
  if (it != local.end()) return it->second;
  return std::nullopt;
}

void Parameters::set_named(const std::string& name, double value) {
  Scope& scope = (!name.empty() && name.front() == '_') ? globals_ : locals_.back();
  scope[name] = value;
}

void Parameters::push_scope() {
  locals_.emplace_back();
  std::array<double, 30> saved{};
  std::copy_n(numbered_.begin() + 1, 30, saved.begin());
  saved_locals_.push_back(saved);
}

void Parameters::pop_scope() {
  if (locals_.size() <= 1) return;
  locals_.pop_back();
  std::copy_n(saved_locals_.back().begin(), 30, numbered_.begin() + 1);
  saved_locals_.pop_back();
}

}  // namespace usina::gcode
