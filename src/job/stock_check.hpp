// The operations checked against the stock (docs/job.md, "Checks against the
// stock"): what a CAM system says before it posts a program for a blank the
// work does not fit. Work off the stock's top face (a hole, a pocket, an
// engraving; a profile wholly beside the blank) or a facing that leaves no
// part is an error: nothing is written. Cutting through the stock, or below
// it further than a breakthrough needs, is a warning: a cut-out is often
// meant, but below the bottom are the parallels or the fixture.
#pragma once

#include <vector>

#include "cam/path.hpp"
#include "core/diagnostic.hpp"
#include "job/geometry.hpp"
#include "job/job_file.hpp"
#include "job/tools.hpp"

namespace usina::job {

// How far a cut may go below the stock's bottom before the warning that it
// cuts what the stock stands on: a profile this much, a drill this much past
// the depth where its full diameter is through (our rule: a clean edge at
// the bottom, and 1 mm is what a sacrificial plate or the gap between
// parallels gives).
constexpr double kBreakthrough = 1.0;
// A drilled hole this much narrower at the bottom than its drill still
// counts as through: a lip of 0.1 mm a side is taken off with the burr (our
// rule).
constexpr double kThroughLip = 0.2;
// Point angles: a DIN 338 jobber drill's (type N, 118°), a spot drill's 90°.
constexpr double kDrillPointAngle = 118.0;
constexpr double kSpotPointAngle = 90.0;
// A tap's chamfered lead, in pitches: the through-hole tap's (DIN 2197
// form B, spiral point) is 3.5 to 5.5. A through thread is full to the
// bottom once the lead has passed it; the library gives no tap's lead, so
// the longest is allowed.
constexpr double kTapLeadPitches = 5.5;

// The stock's top face in the drawing's XY (a rectangle, or a circle about
// the cylinder's centre) and its height below Z0.
struct StockTop {
  bool round = false;
  cam::Vec2 lo, hi;  // the rectangle, or the circle's bounding square
  cam::Vec2 centre;
  double radius = 0;
  double height = 0;
};

StockTop stock_top(const Stock& s);

// How far `p` lies outside the top face, mm; 0 or less: on it.
double outside_by(const StockTop& top, cam::Vec2 p);

// Whether the segment from `a` to `b` meets the top face (its edge included).
bool segment_meets(const StockTop& top, cam::Vec2 a, cam::Vec2 b);

// How far behind its full diameter a drill's tip is: its point's length.
double point_length(double diameter, double point_angle_deg);

// Each check reports at the operation's key that is the cause (layer,
// center, at, depth) and returns false after an error; a warning does not
// stop the job.

// Every hole's centre on the top face.
bool check_hole_centres(const Stock& s, const Operation& op, const std::vector<cam::Vec2>& centres,
                        core::DiagnosticSink& diags);
// A warning for the holes whose circle leaves the top face: their drill
// cuts partly in air at the stock's side and is pushed off its line.
void check_hole_edges(const Stock& s, const Operation& op, const std::vector<HoleGroup>& groups,
                      core::DiagnosticSink& diags);
// A drilling, spot drilling or tapping's depth with `tool` against the height.
bool check_hole_depth(const Stock& s, const Operation& op, const Tool& tool,
                      core::DiagnosticSink& diags);
// The pocket's outline inside the top face; its depth against the height.
bool check_pocket(const Stock& s, const Operation& op, const cam::Path& outline,
                  core::DiagnosticSink& diags);
bool check_ellipse_pocket(const Stock& s, const Operation& op, core::DiagnosticSink& diags);
// No contour wholly off the top face; a contour partly off it a warning.
bool check_profile(const Stock& s, const Operation& op, const std::vector<cam::Path>& contours,
                   core::DiagnosticSink& diags);
// The text's strokes inside the top face.
bool check_engraving(const Stock& s, const Operation& op,
                     const std::vector<std::vector<cam::Vec2>>& strokes,
                     core::DiagnosticSink& diags);
// A facing leaves part of the stock.
bool check_face(const Stock& s, const Operation& op, core::DiagnosticSink& diags);

}  // namespace usina::job
