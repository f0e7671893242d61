#include "dnc/form_fields.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>

namespace usina::dnc {
namespace {

// cam::check_range's message, kept instead of printed.
class FirstMessage final : public core::DiagnosticSink {
 public:
  void report(core::Diagnostic d) override {
    if (message.empty()) message = std::move(d.message);
  }

  std::string message;
};

}  // namespace

const nlohmann::json* FormFields::find(std::string_view name) {
  asked_.emplace_back(name);
  const auto it = body_.find(name);
  if (it == body_.end() || it->is_null()) return nullptr;
  return &*it;
}

void FormFields::describe(FieldSpec spec) {
  if (specs_ == nullptr) return;
  const auto same = [&](const FieldSpec& s) { return s.name == spec.name; };
  if (std::find_if(specs_->begin(), specs_->end(), same) == specs_->end())
    specs_->push_back(std::move(spec));
}

double FormFields::number(std::string_view name, std::string_view what, const cam::Range& range,
                          std::optional<double> fallback) {
  describe({std::string(name), std::string(what), "number", range, fallback, std::nullopt, {}});
  const nlohmann::json* v = find(name);
  if (v == nullptr) {
    if (fallback) return *fallback;
    fail(std::string(name), fmt::format("{} is required", what));
    return 0.0;
  }
  if (!v->is_number()) {
    fail(std::string(name), fmt::format("{} must be a number", what));
    return 0.0;
  }
  const double x = v->get<double>();
  FirstMessage said;
  if (cam::check_range(what, x, range, said)) return x;
  fail(std::string(name), std::move(said.message));
  return 0.0;
}

int FormFields::whole(std::string_view name, std::string_view what, int min, int max,
                      std::optional<int> fallback) {
  const cam::Range range{static_cast<double>(min), static_cast<double>(max), true, ""};
  describe({std::string(name),
            std::string(what),
            "whole",
            range,
            fallback ? std::optional<double>(*fallback) : std::nullopt,
            std::nullopt,
            {}});
  const double x = number(name, what, range, fallback);
  if (x == std::floor(x)) return static_cast<int>(x);
  fail(std::string(name), fmt::format("{} is {:g}; give a whole number", what, x));
  return 0;
}

std::string FormFields::text(std::string_view name, std::string_view what, std::size_t max_chars,
                             std::optional<std::string> fallback) {
  describe({std::string(name),
            std::string(what),
            "text",
            cam::Range{1.0, static_cast<double>(max_chars), true, "characters"},
            std::nullopt,
            fallback,
            {}});
  const nlohmann::json* v = find(name);
  if (v == nullptr) {
    if (fallback) return *fallback;
    fail(std::string(name), fmt::format("{} is required", what));
    return {};
  }
  if (!v->is_string()) {
    fail(std::string(name), fmt::format("{} must be a string", what));
    return {};
  }
  std::string s = v->get<std::string>();
  if (s.empty() || s.size() > max_chars) {
    fail(std::string(name),
         fmt::format("{} has {} characters; give 1 to {}", what, s.size(), max_chars));
    return {};
  }
  return s;
}

std::string FormFields::choice(std::string_view name, std::string_view what,
                               std::initializer_list<std::string_view> choices,
                               std::string_view fallback) {
  FieldSpec spec{
      std::string(name), std::string(what),     "text", cam::Range{1.0, 0.0, true, "characters"},
      std::nullopt,      std::string(fallback), {}};
  std::string list;
  for (const std::string_view c : choices) {
    spec.choices.emplace_back(c);
    spec.range.max = std::max(spec.range.max, static_cast<double>(c.size()));
    list += (list.empty() ? "" : ", ") + std::string(c);
  }
  describe(std::move(spec));
  std::vector<FieldSpec>* specs = std::exchange(specs_, nullptr);
  std::string s = text(name, what, 64, std::string(fallback));
  specs_ = specs;
  if (!s.empty() && std::find(choices.begin(), choices.end(), s) == choices.end()) {
    fail(std::string(name), fmt::format("{} is one of {}", what, list));
    return {};
  }
  return s;
}

void FormFields::fail(std::string field, std::string message, std::string code) {
  // A body of thousands of unknown keys would make an answer larger than
  // itself: the first ones are named, the rest counted in one entry.
  if (errors_.size() > kMaxFieldErrors) return;
  if (errors_.size() == kMaxFieldErrors) {
    errors_.push_back(
        {"", fmt::format("more than {} fields are wrong; the rest are not listed", kMaxFieldErrors),
         std::move(code)});
    return;
  }
  // A field's name is the user's: at most 64 of its characters in the message.
  if (field.size() > kMaxFieldName) field = field.substr(0, kMaxFieldName) + "...";
  errors_.push_back({std::move(field), std::move(message), std::move(code)});
}

void FormFields::refuse_unknown(std::initializer_list<std::string_view> also) {
  for (const auto& [key, value] : body_.items()) {
    const bool known = std::find(asked_.begin(), asked_.end(), key) != asked_.end() ||
                       std::find(also.begin(), also.end(), key) != also.end();
    if (!known) {
      const std::string shown =
          key.size() > kMaxFieldName ? key.substr(0, kMaxFieldName) + "..." : key;
      fail(key, fmt::format("\"{}\" is no field of this cycle", shown));
    }
  }
}

std::string FieldDiagnostics::field_of(const core::Diagnostic& d) const {
  switch (d.code) {
  case core::Code::GenTooMuchWork: return std::string(work_field_);
  case core::Code::GenToolTooBig: return "tool_diameter";
  case core::Code::GenMaterialLeft: return "finish_allowance";
  case core::Code::TextNotInFont: return "text";
  case core::Code::FontUnreadable: return "font";
  case core::Code::DxfUnreadable:
  case core::Code::DxfMalformed:
  case core::Code::DxfNoEntities: return "dxf";
  default: break;
  }
  for (const Phrase& p : phrases_) {
    if (d.message.find(p.words) != std::string::npos) return std::string(p.field);
  }
  return std::string(other_field_);
}

void FieldDiagnostics::report(core::Diagnostic d) {
  if (d.severity != core::Severity::Error) {
    others.push_back(std::move(d));
    return;
  }
  std::string field = field_of(d);
  if (d.loc.line != 0) d.message += fmt::format(" (line {} of the drawing)", d.loc.line);
  errors.push_back({std::move(field), std::move(d.message), std::string(core::code_name(d.code))});
}

}  // namespace usina::dnc
