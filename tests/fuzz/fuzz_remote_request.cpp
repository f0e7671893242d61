// libFuzzer target for what a control punches: the input is the rows read
// from the link, through the tape reader (the code and end of block picked
// by the first byte), then the text through the remote-request parser, and
// a refusal through the response program. Any input must give a text, a
// request or a refusal, never a crash or a hang; a request's program name is
// never a path, and the response program is punchable in EIA.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <string_view>

#include "dnc/remote_request.hpp"
#include "dnc/tape_code.hpp"
#include "dnc/tape_reader.hpp"

namespace {

using usina::dnc::EndOfBlock;
using usina::dnc::TapeCode;

void check(bool ok) {
  if (!ok) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::uint8_t pick = data[0];
  const auto code = static_cast<TapeCode>(pick % 3U);
  auto eob = static_cast<EndOfBlock>((pick >> 2U) % 5U);
  if (code == TapeCode::Eia && (eob == EndOfBlock::Semicolon || eob == EndOfBlock::Hash)) {
    eob = EndOfBlock::Cr;
  }
  usina::dnc::TapeReader reader(code, eob, (pick & 0x40U) != 0, 1U << 20U);
  reader.feed(std::span<const std::uint8_t>(data + 1, size - 1));
  const usina::dnc::RequestRules rules{(pick & 0x80U) != 0 ? 0U : 9999U, 10};
  const auto request = usina::dnc::parse_remote_request(reader.text(), rules);
  if (request && *request) {
    check(usina::dnc::valid_program_name((*request)->program));
    check((*request)->program.find('/') == std::string::npos);
  }
  if (request && !*request) {
    const std::string response = usina::dnc::response_program(9999, request->error());
    for (const char c : response) {
      check(usina::dnc::encode_char(TapeCode::Eia, static_cast<unsigned char>(c)).has_value());
    }
  }
  // The raw input as a text, too: a request typed into a file.
  (void)usina::dnc::parse_remote_request(
      std::string_view(reinterpret_cast<const char*>(data), size), rules);
  return 0;
}
