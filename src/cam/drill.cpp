#include "cam/drill.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

namespace usina::cam {
namespace {

// The hole's moves as src/gcode/interp/canned_cycles.cpp (after LinuxCNC's
// interp_cycles.cc) makes them in G98 mode, the clear level at the safe Z.
void drill_moves(ProgramWriter& w, Vec2 at, const DrillOptions& o) {
  const double r = o.retract;
  const double bottom = -o.depth;
  auto to = [&](double z) { return Vec3{at.x, at.y, z}; };
  if (o.peck > 0.0) {
    // G83: out to R after each peck, back down to the clearance above the
    // last depth; the repeated subtraction decides the last peck, as there.
    double d = r - o.peck;
    while (d > bottom) {
      w.feed(to(d));
      w.rapid(to(r));
      w.rapid(to(d + o.peck_clearance));
      d -= o.peck;
    }
  }
  w.feed(to(bottom));
  if (o.bore && o.bore_cycle == canon::HoleCycle::BoreStop) {
    // G86: stopped, so the edge is not dragged round as it comes out.
    w.emit(canon::Spindle{0.0, canon::SpindleDir::Off});
    w.rapid(to(o.cut.safe_z));
    w.emit(canon::Spindle{o.cut.rpm, canon::SpindleDir::Cw});
    return;
  }
  if (o.bore && o.bore_cycle == canon::HoleCycle::BoreDwell) w.emit(canon::Dwell{o.dwell});
  if (o.bore) w.feed(to(r));
  if (o.pitch > 0.0) {
    w.emit(canon::Spindle{o.cut.rpm, canon::SpindleDir::Ccw});
    w.feed(to(r));
    w.emit(canon::Spindle{o.cut.rpm, canon::SpindleDir::Cw});
  }
  w.rapid(to(o.cut.safe_z));
}

// How the title says a bore leaves its holes.
std::string bore_words(const DrillOptions& o) {
  switch (o.bore_cycle) {
  case canon::HoleCycle::BoreDwell: return fmt::format(", bored (dwell {:g} s, fed out)", o.dwell);
  case canon::HoleCycle::BoreStop: return ", bored (spindle stopped, out at rapid)";
  case canon::HoleCycle::Bore:
  case canon::HoleCycle::Drill: break;
  }
  return ", bored (fed out)";
}

// The pecks of one hole, as drill_moves makes them (with none: one feed).
double pecks(const DrillOptions& o) {
  return o.peck > 0.0 ? std::ceil((o.depth + o.retract) / o.peck) : 1.0;
}

// A bore's cycle and its dwell: only G89 dwells, and for a time that makes
// sense at the bottom of a hole.
bool check_bore_cycle(const DrillOptions& o, core::DiagnosticSink& diags) {
  using canon::HoleCycle;
  const HoleCycle c = o.bore ? o.bore_cycle : HoleCycle::Drill;
  if (o.bore && c == HoleCycle::Drill)
    return fail(diags, core::Code::GenBadValue, "a bore's cycle is G85, G89 or G86, not G81");
  if (c == HoleCycle::BoreDwell)
    return check_range("the dwell", o.dwell, Range{0.001, kMaxBoreDwell, true, "s"}, diags);
  if (o.dwell != 0.0)
    return fail(diags, core::Code::GenBadValue,
                "only a G89 bore dwells at the bottom: give no dwell for another cycle");
  return true;
}

bool check_ranges(const DrillOptions& o, core::DiagnosticSink& diags) {
  bool ok = check_cutting(o.cut, diags);
  ok = check_range("the depth (--depth)", o.depth, kLength, diags) && ok;
  ok = check_range("the retract height (--retract)", o.retract, kLengthOrZero, diags) && ok;
  ok = check_range("the peck (--peck)", o.peck, kLengthOrZero, diags) && ok;
  ok = check_range("the peck clearance", o.peck_clearance, kLengthOrZero, diags) && ok;
  ok = check_range("the thread pitch", o.pitch, kLengthOrZero, diags) && ok;
  if (ok && o.pitch > 0.0 && o.peck > 0.0)
    ok = fail(diags, core::Code::GenBadValue, "a tap is not pecked: give no peck with a pitch");
  if (ok && o.bore && (o.pitch > 0.0 || o.peck > 0.0))
    ok = fail(diags, core::Code::GenBadValue, "a bore is neither pecked nor tapped");
  if (ok && o.pitch > 0.0 && o.form == HoleForm::Features)
    ok = fail(diags, core::Code::GenBadValue, "tapping is written as moves, not as a drill cycle");
  return ok && check_bore_cycle(o, diags);
}

// A peck as deep as the hole drills it in one feed, as G81 does: legal, but
// rarely what was meant (a peck in the wrong units, the wrong option).
void warn_peck_unused(const DrillOptions& o, core::DiagnosticSink& diags) {
  if (o.peck <= 0.0 || o.peck < o.depth + o.retract) return;
  diags.report({core::Code::GenNoEffect,
                core::Severity::Warning,
                {},
                fmt::format("the peck {:g} mm is not less than the hole's {:g} mm from the R "
                            "plane to the bottom: each hole is drilled in one feed, as without "
                            "--peck",
                            o.peck, o.depth + o.retract)});
}

bool check_drill(const std::vector<Vec2>& points, const DrillOptions& o,
                 core::DiagnosticSink& diags) {
  if (!check_ranges(o, diags)) return false;
  if (o.retract > o.cut.safe_z) {
    return fail(diags, core::Code::GenBadValue,
                fmt::format("the retract height {:g} mm is above the safe Z {:g} mm; the R "
                            "plane must be at or below the safe Z",
                            o.retract, o.cut.safe_z));
  }
  if (pecks(o) > 100000.0) {
    return fail(diags, core::Code::GenBadValue,
                fmt::format("a peck of {:g} mm makes more than 100000 pecks a hole", o.peck));
  }
  if (points.empty()) return fail(diags, core::Code::GenBadValue, "there are no holes to drill");
  if (points.size() > 10 * static_cast<std::size_t>(kMaxPasses)) {
    return fail(diags, core::Code::GenBadValue,
                fmt::format("{} holes are more than {}", points.size(), 10 * kMaxPasses));
  }
  for (const Vec2& p : points) {
    if (!check_point("the hole at", p, diags)) return false;
  }
  // A post expands a G83 into its pecks for a control without cycles: the
  // pecks count whatever the form.
  const double moves = static_cast<double>(points.size()) * (3 * pecks(o) + 4) + 10;
  if (!check_work("the drilling", moves, o.cut.max_moves, "give a larger peck or fewer holes",
                  diags)) {
    return false;
  }
  warn_peck_unused(o, diags);
  return true;
}

}  // namespace

std::vector<Vec2> bolt_circle(Vec2 center, double radius, int count, double start_deg) {
  std::vector<Vec2> out;
  for (int i = 0; i < count; ++i) {
    const double a = (start_deg + 360.0 * i / count) * std::numbers::pi / 180.0;
    out.push_back({center.x + radius * std::cos(a), center.y + radius * std::sin(a)});
  }
  return out;
}

std::vector<Vec2> grid(Vec2 origin, int nx, int ny, double dx, double dy) {
  std::vector<Vec2> out;
  for (int j = 0; j < ny; ++j) {
    for (int k = 0; k < nx; ++k) {
      const int i = j % 2 == 0 ? k : nx - 1 - k;
      out.push_back({origin.x + dx * i, origin.y + dy * j});
    }
  }
  return out;
}

bool generate_drill(const std::vector<Vec2>& points, const DrillOptions& given, canon::Sink& sink,
                    core::DiagnosticSink& diags) {
  DrillOptions o = given;
  if (o.pitch > 0.0) o.cut.feed = o.cut.plunge_feed = o.pitch * o.cut.rpm;  // synchronised
  if (!check_drill(points, o, diags)) return false;
  ProgramWriter w(sink, o.cut);
  const canon::HoleCycle cycle = o.bore ? o.bore_cycle : canon::HoleCycle::Drill;
  w.begin(fmt::format("usina gen drill: {} holes, depth {:g} mm{}{}", points.size(), o.depth,
                      o.peck > 0.0 ? fmt::format(", peck {:g} mm", o.peck) : std::string(),
                      o.pitch > 0.0 ? fmt::format(", tapped, pitch {:g} mm", o.pitch)
                      : o.bore      ? bore_words(o)
                                    : std::string()));
  w.rapid_over(points.front());
  if (o.form == HoleForm::Features) {
    // Each hole carries its feed (the plunge feed: the whole cut is along
    // Z): the cycle goes to R at rapid, as a control's own does.
    for (const Vec2& q : points) {
      w.emit(canon::Hole{{q.x, q.y, o.retract},
                         o.cut.tool_diameter,
                         o.retract + o.depth,
                         cycle,
                         o.cut.plunge_feed,
                         o.dwell});
    }
    w.end();
    return true;
  }
  w.set_origin(canon::Origin::Cycle);
  for (const Vec2& p : points) {
    w.rapid({p.x, p.y, o.cut.safe_z});
    if (o.cut.safe_z > o.retract) w.rapid({p.x, p.y, o.retract});
    w.emit(canon::Hole{{p.x, p.y, o.retract},
                       o.cut.tool_diameter,
                       o.retract + o.depth,
                       cycle,
                       std::nullopt,
                       o.dwell});
    drill_moves(w, p, o);
  }
  w.set_origin(canon::Origin::Program);
  w.end();
  return true;
}

}  // namespace usina::cam
