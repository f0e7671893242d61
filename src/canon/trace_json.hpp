// One op as its JSONL line of spec/trace.md (no newline), appended to a
// buffer: the writer of `usina trace --format jsonl`, hot for large programs.
#pragma once

#include <string_view>

#include <fmt/format.h>

#include "canon/op.hpp"

namespace usina::canon {

// `file` names the op's file when it is not the program's own (JSONL "file").
void append_jsonl(fmt::memory_buffer& buf, const Op& op, std::string_view file = {});

}  // namespace usina::canon
