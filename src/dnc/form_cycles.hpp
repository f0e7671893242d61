// The web page's forms for cycles (issue 14, conversational programming):
// a cycle's fields, as JSON, made into a program for one control by the
// generators of `usina gen` (src/cam) and its posts, with the same range
// checks and the same bound on the work, checked before anything is made.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/diagnostic.hpp"
#include "dnc/form_fields.hpp"

namespace usina::dnc {

// The bound on a form's work: moves (canon ops, a block of G-code each,
// about 18 bytes: 18 MB of G-code), estimated from the fields before any is
// made (docs/gen.md, "The work is bounded before it starts"). `usina gen`'s
// default is 20 times this; a preview is a program a shop reviews in a
// browser, and the server runs it through the interpreter twice (the check
// and the tool path). A `max_moves` field may lower it, never raise it.
inline constexpr double kFormMaxMoves = 1'000'000;

// The cycles, in the order the page lists them.
const std::vector<std::string_view>& form_cycles();
bool is_form_cycle(std::string_view cycle);

struct FormProgram {
  std::string dialect;                  // the post's control: rs274ngc, fanuc, grbl, romi
  std::string text;                     // the program; empty when there are errors
  std::vector<FieldError> errors;       // every bad field; nothing was generated
  std::vector<core::Diagnostic> notes;  // the generator's and the post's warnings
};

// Every cycle's fields as its reading asks for them (FieldSpec), for the
// page (GET /api/forms): {"cycles": [{"name", "fields": [{"name", "what",
// "kind", "unit", "min", "max", "min_included", "default", "choices"}]}]}.
nlohmann::json form_specs();

// `body`: the cycle's fields and "dialect" (and "machine_class", which is
// the caller's). Never throws for bad input.
FormProgram form_program(std::string_view cycle, const nlohmann::json& body);

}  // namespace usina::dnc
