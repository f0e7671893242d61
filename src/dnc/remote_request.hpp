// Remote requests: the operator asks for a program from the control's own
// keyboard by punching a small program (research/dnc.md §2.4, CIMCO style):
//
//   O9999                       the machine's request program number
//   (PRG=1234)                  the program wanted
//   (/REQ 1234 /BL 10020)       the same, starting at block N10020
//   (PRG=1234 TO=2)  (/LI 120)  starting at tool T2, at line 120
//   (OP=JOHN)  (/OP JOHN)       the operator who asks
//
// Only the first `request_lines` lines are read. A punched program is a
// request when its O number is the machine's request_program (any program
// with a request comment when request_program is 0). A request that cannot
// be answered (no name, a name that could be a path, a start that is not a
// number) is an error the control is told about in a response program.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include <tl/expected.hpp>

namespace usina::dnc {

struct RequestRules {
  std::uint32_t request_program = 9999;  // 0: any program with a request comment
  std::uint32_t scan_lines = 10;
};

struct RemoteRequest {
  std::string program;
  std::optional<std::uint64_t> start_block;
  std::optional<std::uint64_t> start_line;
  std::optional<std::uint32_t> start_tool;
  std::string operator_name;
};

// Nothing when `text` is no request; the request, or why it cannot be
// answered, when it is one.
std::optional<tl::expected<RemoteRequest, std::string>> parse_remote_request(
    std::string_view text, const RequestRules& rules);

// A name a program may have in the store: 1 to 64 letters, digits, `_`,
// `-`, `.`, not starting with `.` or `-` (so never a path or `..`).
bool valid_program_name(std::string_view name);

// The short program that tells the operator why a request gets no program:
// O<number>, the message as comments (upper case, only characters every
// tape code has, at most 60 a line), M30.
std::string response_program(std::uint32_t number, std::string_view message);

}  // namespace usina::dnc
