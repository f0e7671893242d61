// The 2.5D arithmetic of contouring (research/apt.md §5.2): the tool-centre
// path along a line or circle drive surface at the cutter offset, the stop
// point on a check surface (TO, ON, PAST, TANTO, the n-th intersection),
// the startup positions of GO/, and the segmentation of a circular path
// within INTOL/OUTTOL as IBM's processor does it (§5.3, its ASEGMT).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "apt/geometry.hpp"
#include "apt/plane_geometry.hpp"

namespace usina::apt {

// How the tool stands to a surface: TO (tangent, near side), ON (centre on
// it), PAST (tangent, far side), TANTO (where drive and check are tangent).
enum class Stop : unsigned char { To, On, Past, Tanto };

// A drive or check surface in the plane: a line or a circle (a vertical
// plane counts as its line).
struct Curve {
  bool circle = false;
  Line2 line;
  Circle2 round;
};

// The curve of a LINE, CIRCLE or vertical PLANE; empty for other geometry.
std::optional<Curve> curve_of(const Geom& g);

// The z of a horizontal plane; empty for any other geometry.
std::optional<double> horizontal_z(const Geom& g);

// How far the point `p` is from the curve (its unsigned distance).
double distance_to(const Curve& c, Vec2 p);

// The tool-centre path of one motion: a line through `start` along `t`, or
// a circle about `c` of radius `rho` travelled counter-clockwise (sense +1)
// or clockwise (-1).
struct Path {
  bool circle = false;
  Vec2 start;
  Vec2 t;  // line: the unit direction of travel
  Vec2 c;  // circle: the centre
  double rho = 0.0;
  int sense = 1;
};

// Where the motion goes: GOLFT, GORGT, GOFWD, GOBACK.
enum class Turn : unsigned char { Left, Right, Forward, Back };

// The path from `te` along the drive surface `ds`, the direction chosen
// against `fwd` as `turn` says, the tool on side `side` (+1 TLLFT, -1
// TLRGT, 0 TLON) at radius `r`. Fails (with the reason) when the direction
// is ambiguous or the tool is not at the cutter offset within `tol`.
std::optional<Path> drive_path(const Curve& ds, Vec2 te, Vec2 fwd, Turn turn, int side, double r,
                               double tol, std::string& why);

// The stop point of `path` on the check surface `cs` (the `nth` one, from
// 1), the cutter of radius `r`, `ds` the drive surface for TANTO.
std::optional<Vec2> stop_point(const Path& path, const Curve& ds, const Curve& cs, Stop stop,
                               int nth, double r, std::string& why);

// The direction of travel at `p` on `path`.
Vec2 tangent_at(const Path& path, Vec2 p);

// The startup position against one surface: the tool moved from `te` to
// the nearest point where it stands `stop` to `s`.
std::optional<Vec2> startup_one(const Curve& s, Vec2 te, Stop stop, double r, std::string& why);

// The startup position against a drive and a check surface: the meeting
// point of their offsets nearest `te`.
std::optional<Vec2> startup_two(const Curve& ds, Stop ds_stop, const Curve& cs, Stop cs_stop,
                                Vec2 te, double r, std::string& why);

// The points IBM's processor writes along a circular path from `te` to
// `end` (not `end` itself): chords within the band INTOL/OUTTOL on the
// side away from the part; `convex` when the tool is outside the drive
// circle; `widen` is added to the band (IBM's 0.00005, see the caller).
// Fails when the band is empty or would take more than `most` points.
std::optional<std::vector<Vec2>> segment_arc(const Path& path, Vec2 te, Vec2 end, double intol,
                                             double outtol, bool convex, double widen,
                                             std::size_t most, std::string& why);

}  // namespace usina::apt
