// What Grbl checks from the position, which only the interpreter's moves
// give: an arc's end on its circle within Grbl's tolerance, a probe going
// somewhere, the soft limits. Checked on the ops of one block before they
// are passed on, so a refused block sends nothing (grbl/runner.cpp).
#pragma once

#include <optional>
#include <vector>

#include "canon/op.hpp"
#include "core/diagnostic.hpp"
#include "gcode/grbl/dialect.hpp"

namespace usina::gcode::grbl {

class MachineCheck {
 public:
  explicit MachineCheck(const core::Vec3& start) : at_{start, true} {}

  // The first failure of the block whose ops are `ops`, made under `facts`:
  // error:33 or error:15 (the block is refused), or ALARM:2 (the run
  // ends). On a failure the position is left where the block started.
  std::optional<core::Diagnostic> block(const std::vector<canon::Op>& ops,
                                        const MachineFacts& facts);

 private:
  struct Position {
    core::Vec3 pos;
    bool known = true;  // false after a probe: it stops short of its target
  };

  void op(const canon::Op& op);
  void moved(const core::Vec3& to, const core::SourceLoc& src);
  void travel(const core::Vec3& to, const core::SourceLoc& src);
  void check_arc(const canon::Arc& a, const core::SourceLoc& src);
  void arc_travel(const canon::Arc& a, const core::SourceLoc& src);
  void fail(const core::SourceLoc& src, int number, std::string_view detail);

  Position at_;
  const MachineFacts* facts_ = nullptr;
  std::optional<core::Diagnostic> failure_;
};

}  // namespace usina::gcode::grbl
