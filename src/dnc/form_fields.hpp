// A cycle form's fields as the page sends them (docs/dnc-server.md, "Forms
// for cycles"): a JSON object of numbers and strings, read one field at a
// time with the range `usina gen` checks it against (cam/limits.hpp), so
// that every bad field is named in the answer, not only the first one.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "cam/limits.hpp"
#include "core/diagnostic.hpp"

namespace usina::dnc {

// One bad field: its name in the body ("" for the form as a whole), what is
// wrong with it, and the diagnostic code `usina gen` gives it.
struct FieldError {
  std::string field;
  std::string message;
  std::string code = "E_GEN_BAD_VALUE";
};

// Coordinates: within ±100 m of the origin, as cam::check_point has them.
inline constexpr cam::Range kCoordinate{-cam::kMaxCoordinate, cam::kMaxCoordinate, true, "mm"};

// The bad fields an answer names at most (one more entry says there were
// more), and the characters of a field's name it repeats.
inline constexpr std::size_t kMaxFieldErrors = 100;
inline constexpr std::size_t kMaxFieldName = 64;

// A field as a cycle's reading asks for it: what the page needs to check
// it as the user types (GET /api/forms), taken from the very reading the
// server checks a form with, so the two cannot disagree.
struct FieldSpec {
  std::string name;
  std::string what;  // how a message names it ("the tool diameter")
  std::string kind;  // "number", "whole" or "text"
  cam::Range range;  // of a number; of a text, 1 to its most characters
  std::optional<double> number_default;
  std::optional<std::string> text_default;
  std::vector<std::string> choices;  // a text that must be one of these
};

class FormFields {
 public:
  explicit FormFields(const nlohmann::json& body) : body_(body) {}

  // Every field read from now on is also described into `specs` (in the
  // order read; a field read twice once).
  void describe_into(std::vector<FieldSpec>& specs) { specs_ = &specs; }

  // The number `name` (`what` says it in a message): `fallback` when it is
  // absent, an error when it is absent and has none, is no number, or is out
  // of `range`. After an error: 0 (nothing is generated then).
  double number(std::string_view name, std::string_view what, const cam::Range& range,
                std::optional<double> fallback);
  // A whole number from `min` to `max`.
  int whole(std::string_view name, std::string_view what, int min, int max,
            std::optional<int> fallback);
  // A string of 1 to `max_chars` characters.
  std::string text(std::string_view name, std::string_view what, std::size_t max_chars,
                   std::optional<std::string> fallback);

  // A text that is one of `choices` (`fallback`, when absent, is one).
  std::string choice(std::string_view name, std::string_view what,
                     std::initializer_list<std::string_view> choices, std::string_view fallback);

  void fail(std::string field, std::string message, std::string code = "E_GEN_BAD_VALUE");

  // Every key of the body that no reading asked for is an error: a misspelt
  // field would silently take its default. `also` are keys read elsewhere.
  void refuse_unknown(std::initializer_list<std::string_view> also);

  const std::vector<FieldError>& errors() const { return errors_; }

  std::vector<FieldError> take_errors() { return std::move(errors_); }

  bool ok() const { return errors_.empty(); }

 private:
  const nlohmann::json* find(std::string_view name);
  void describe(FieldSpec spec);

  const nlohmann::json& body_;
  std::vector<std::string> asked_;
  std::vector<FieldError> errors_;
  std::vector<FieldSpec>* specs_ = nullptr;
};

// A generator's diagnostics for a form: errors become FieldErrors (the
// field found by the code, else by the first of `phrases` in the message),
// a drawing's errors to "dxf" with their line; warnings and notes are
// kept for the preview's diagnostics.
class FieldDiagnostics final : public core::DiagnosticSink {
 public:
  struct Phrase {
    std::string_view words;
    std::string_view field;
  };

  // `work_field`: where too much work is said (the value that most changes
  // it); `other_field`: where an error goes that nothing else names.
  FieldDiagnostics(std::vector<Phrase> phrases, std::string_view work_field,
                   std::string_view other_field = "")
      : phrases_(std::move(phrases)), work_field_(work_field), other_field_(other_field) {}

  void report(core::Diagnostic d) override;

  std::vector<FieldError> errors;
  std::vector<core::Diagnostic> others;

 private:
  std::string field_of(const core::Diagnostic& d) const;

  std::vector<Phrase> phrases_;
  std::string_view work_field_;
  std::string_view other_field_;
};

}  // namespace usina::dnc
