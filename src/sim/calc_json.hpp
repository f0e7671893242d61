// The calculators of calc.hpp as JSON: the object `usina calc --format json`
// prints and the server's `POST /api/calc/{name}` answers (the page's
// calculators), `{"calculation": NAME, "inputs": {...}, "results": {...}}`
// with the field names of src/cli/calc.cpp's header, and the inputs read
// back from such an object for the server.
#pragma once

#include <string_view>

#include <nlohmann/json.hpp>

#include "sim/calc.hpp"

namespace usina::sim {

nlohmann::json calc_json(const OpenLoopInput& in, const OpenLoop& r);
nlohmann::json calc_json(const ClosedLoopInput& in, const ClosedLoop& r);
nlohmann::json calc_json(const PrecisionInput& in, const Precision& r);
nlohmann::json calc_json(const CuttingInput& in, const Cutting& r);
// `numeral` as it was given (leading zeros are digits of the code).
nlohmann::json calc_json(std::string_view numeral, const Bcd& r);

// The calculation `name` (open-loop, closed-loop, precision, cutting or
// bcd) of `inputs`, a JSON object of the input field names: the whole
// answer, or the message of the first input missing, unknown, not a number
// or not whole, or the calculation's own. bcd's `numeral` is text ("0125":
// its zeros are digits) or a whole number of JSON.
Checked<nlohmann::json> calc_from_json(std::string_view name, const nlohmann::json& inputs);

}  // namespace usina::sim
