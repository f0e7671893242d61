// An error a machining module (canned cycles, cutter compensation) finds
// while it executes a block: its code and message; the interpreter adds the
// block's location when it reports it. Outside the block loop a fallible
// step returns tl::expected (DESIGN.md, "One road below the text").
#pragma once

#include <string>
#include <utility>

#include <tl/expected.hpp>

#include "core/diagnostic.hpp"

namespace usina::gcode {

struct InterpError {
  core::Code code = core::Code::Unsupported;
  std::string message;
};

// A step that succeeds with nothing to say, or fails with the block's error.
using InterpResult = tl::expected<void, InterpError>;

inline tl::unexpected<InterpError> interp_error(core::Code code, std::string message) {
  return tl::unexpected<InterpError>(InterpError{code, std::move(message)});
}

}  // namespace usina::gcode
