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

// The ops of one line, held until its checks pass: those built, and the
// straight moves that went by unbuilt (the run's sink reads no op: usina
// check), each with its end and block, in its place among them.
struct LineMoves {
  struct Passed {
    std::size_t before;  // the count of built ops sent before it
    core::SourceLoc src;
    core::Vec3 to;
  };

  std::vector<canon::Op> built;
  std::vector<Passed> passed;

  void clear() {
    built.clear();
    passed.clear();
  }

  // Each in the order sent, until a visit returns false.
  template <class OnBuilt, class OnPassed>
  void each(OnBuilt&& on_built, OnPassed&& on_passed) const {
    if (passed.empty()) {  // a sink that reads ops: every move built
      for (const canon::Op& op : built)
        if (!on_built(op)) return;
      return;
    }
    std::size_t k = 0;
    for (std::size_t i = 0; i <= built.size(); ++i) {
      for (; k < passed.size() && passed[k].before == i; ++k)
        if (!on_passed(passed[k])) return;
      if (i < built.size() && !on_built(built[i])) return;
    }
  }
};

class MachineCheck {
 public:
  explicit MachineCheck(const core::Vec3& start) : at_{start, true} {}

  // The first failure of the block whose moves are `moves`, made under `facts`:
  // error:33 or error:15 (the block is refused), or ALARM:2 (the run
  // ends). On a failure the position is left where the block started.
  std::optional<core::Diagnostic> block(const LineMoves& moves, const MachineFacts& facts);

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
