// A bare hole: a Hole op with Origin::Program is a feature a generator
// writes (usina gen drill, a job's drilling), with no moves of its own; the
// post drills it as G81 where the control has canned cycles, else as moves
// (post/writer_hole.cpp). The back ends that follow the tool (stats,
// simulate) take it as the moves LinuxCNC's G81 makes in G98: from where the
// tool is, up to R if it is below it, over the hole, down to R, at the last
// feed rate to the bottom, and back to where it started or to R if that was
// lower. A bored hole (HoleCycle::Bore) is fed back out to R before that,
// as LinuxCNC's G85; HoleCycle::BoreDwell dwells at the bottom first (G89
// in G99: out to R, as a Fanuc's G89 in either mode); HoleCycle::BoreStop
// stops the spindle at the bottom, rapids to where it started and starts
// the spindle again (G86). A Hole with Origin::Cycle comes with its cycle's
// moves: nothing more.
#pragma once

#include <vector>

#include "canon/op.hpp"

namespace usina::canon {

// The moves of a bare hole `h` (the op `hole`, whose source they keep, as
// cycle moves) with the tool at `from` and the rotary axes at `abc`,
// drilling at the hole's feed rate, else at `feed` (the last feed move's),
// the spindle `spindle` (started again after a G86); none when the hole is
// not bare or has no depth.
std::vector<Op> bare_hole_moves(const Op& hole, const Hole& h, const Vec3& from, const Abc& abc,
                                const Feed& feed, const Spindle& spindle = {});

}  // namespace usina::canon
