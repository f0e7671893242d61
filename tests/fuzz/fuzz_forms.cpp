// libFuzzer target for the web page's forms for cycles (POST
// /api/forms/{cycle}/preview; dnc/form_cycles.hpp): the first byte picks the
// cycle, the rest is the request's JSON body, read as the server reads it
// (nlohmann, no exceptions), then made into a program for its control by
// the generators and posts. Any body must give a program or its field
// errors, never a crash, a hang or a non-finite number in the program.
// The work is bounded by the form's own max_moves field, which may lower
// the server's bound (1,000,000 moves): here it is lowered to 20,000 so a
// run stays short, and the bound's path is still taken.
#include <cctype>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "dnc/form_cycles.hpp"

namespace {

constexpr double kFuzzMaxMoves = 20'000;

// A number the post wrote as "nan" or "inf" is a non-finite value that
// reached the program. Comments are left out: they carry the engraved text
// and the user's words.
void trap_on_non_finite(const std::string& text) {
  std::string words;
  bool comment = false, to_line_end = false;
  for (const char c : text) {
    if (c == '\n') to_line_end = false;
    if (c == '(') comment = true;
    if (c == ';') to_line_end = true;
    if (!comment && !to_line_end)
      words += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (c == ')') comment = false;
  }
  if (words.find("nan") != std::string::npos || words.find("inf") != std::string::npos)
    std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace usina::dnc;
  if (size == 0) return 0;
  const auto& cycles = form_cycles();
  const std::string_view cycle = cycles[data[0] % cycles.size()];
  const std::string_view text(reinterpret_cast<const char*>(data) + 1, size - 1);
  nlohmann::json body = nlohmann::json::parse(text, nullptr, false);
  if (body.is_discarded() || !body.is_object()) return 0;
  const auto given = body.find("max_moves");
  if (given == body.end() || !given->is_number() || !(given->get<double>() <= kFuzzMaxMoves))
    body["max_moves"] = kFuzzMaxMoves;
  const FormProgram p = form_program(cycle, body);
  if (!p.errors.empty() && !p.text.empty()) std::abort();  // errors: nothing was generated
  trap_on_non_finite(p.text);
  return 0;
}
