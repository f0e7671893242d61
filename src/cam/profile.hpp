// Profile milling (seed 004, table 7.5, "usinagem de perfil"): the tool
// around a contour at a constant depth, a tool radius outside or inside it,
// in equal depth passes, entering and leaving along tangent arcs, with tabs
// that hold the part to the stock on the last passes.
#pragma once

#include <optional>
#include <string_view>

#include "cam/path.hpp"
#include "cam/program.hpp"

namespace usina::cam {

// Outside/Inside for a closed contour; Left/Right (seen along the drawn
// direction) for any contour; On runs the tool centre on the line. Auto
// takes each closed contour by its nesting in the others: one inside an even
// number of contours (0: the part's outline) is cut outside, one inside an odd
// number (a hole in the part) inside.
enum class ProfileSide { Outside, Inside, Left, Right, On, Auto };

// The side as usina gen profile's --side and a job's `side` name it
// ("outside", "inside", "left", "right", "on", "auto"); nullopt for another.
std::optional<ProfileSide> profile_side(std::string_view name);

struct Tabs {
  int count = 0;        // 0: no tabs
  double width = 3.0;   // mm of material left along the contour
  double height = 1.0;  // mm of material left above the bottom
};

struct ProfileOptions {
  Cutting cut;
  double depth = 1.0;      // mm below the top
  double step_down = 1.0;  // largest depth of one pass
  ProfileSide side = ProfileSide::Outside;
  double lead_radius = 0.0;  // mm; 0 for no lead arcs
  Tabs tabs;
  double tolerance = 0.001;
  // The tool centre's distance from the contour; unset: the tool's radius
  // (a cylinder's side on the line). A chamfer mill's cone meets the edge
  // nearer its axis than its diameter: the job gives it (job/tools.hpp,
  // chamfer_cut). 0 runs the centre on the contour, in the side's direction.
  std::optional<double> offset;
};

// The tool-centre paths for `contour`: offset a tool radius to the side and,
// for a closed contour cut inside or outside, walked for climb milling with
// the spindle clockwise (the part on the tool's right: clockwise outside,
// counter-clockwise inside). Empty when the tool does not fit.
std::vector<Path> profile_paths(const Path& contour, const ProfileOptions& o);

// How many of the other closed contours hold each contour (tested at its
// start point; contours that cross each other are not a drawing of a part).
std::vector<int> nesting_depths(const std::vector<Path>& contours, double tolerance);

// +1 when the lead arcs are on the left of the tool-centre path, −1 right:
// the side away from the part.
int lead_side(ProfileSide side);

// Checks, then the passes. False, with nothing emitted, after an error.
bool generate_profile(const std::vector<Path>& contours, const ProfileOptions& o, canon::Sink& sink,
                      core::DiagnosticSink& diags);

}  // namespace usina::cam
