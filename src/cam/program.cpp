#include "cam/program.hpp"

#include <cmath>

#include <fmt/format.h>

namespace usina::cam {

bool fail(core::DiagnosticSink& diags, core::Code code, std::string message) {
  diags.report({code, core::Severity::Error, {}, std::move(message)});
  return false;
}

bool check_positive(std::string_view what, double value, std::string_view unit,
                    core::DiagnosticSink& diags, bool zero_ok) {
  if (std::isfinite(value) && (value > 0.0 || (zero_ok && value == 0.0))) return true;
  return fail(
      diags, core::Code::GenBadValue,
      fmt::format("{} is {:g}{}; it must be a number {} zero", what, value,
                  unit.empty() ? "" : fmt::format(" {}", unit), zero_ok ? "at or above" : "above"));
}

bool check_cutting(const Cutting& c, core::DiagnosticSink& diags) {
  bool ok = check_positive("the tool diameter", c.tool_diameter, "mm", diags);
  ok = check_positive("the feed", c.feed, "mm/min", diags) && ok;
  ok = check_positive("the plunge feed", c.plunge_feed, "mm/min", diags) && ok;
  ok = check_positive("the spindle speed", c.rpm, "rev/min", diags) && ok;
  ok = check_positive("the safe Z", c.safe_z, "mm", diags) && ok;
  if (c.tool < 0) {
    ok = fail(diags, core::Code::GenBadValue,
              fmt::format("tool number {} is negative; give 0 or more", c.tool));
  }
  return ok;
}

bool check_point(std::string_view what, Vec2 p, core::DiagnosticSink& diags) {
  if (std::isfinite(p.x) && std::isfinite(p.y) && std::fabs(p.x) <= kMaxCoordinate &&
      std::fabs(p.y) <= kMaxCoordinate) {
    return true;
  }
  return fail(diags, core::Code::GenBadValue,
              fmt::format("{} ({:g}, {:g}) is beyond ±{:g} mm of the origin", what, p.x, p.y,
                          kMaxCoordinate));
}

bool check_extent(const std::vector<Path>& paths, core::DiagnosticSink& diags) {
  for (const Path& p : paths) {
    if (!check_point("a contour's point", p.start, diags)) return false;
    for (const PathSegment& s : p.segs) {
      if (!check_point("a contour's point", s.to, diags)) return false;
      if (s.center && !check_point("an arc's centre", *s.center, diags)) return false;
    }
  }
  return true;
}

bool check_passes(double depth, double step, core::DiagnosticSink& diags) {
  if (depth / step <= kMaxPasses) return true;
  return fail(diags, core::Code::GenBadValue,
              fmt::format("a depth of {:g} mm in steps of {:g} mm makes more than {} passes", depth,
                          step, kMaxPasses));
}

std::vector<double> depth_levels(double depth, double step) {
  // The tiny allowance keeps 6 / 2 at three passes despite rounding.
  const auto n = static_cast<int>(std::ceil(depth / step - 1e-9));
  std::vector<double> z;
  for (int i = 1; i < n; ++i)
    z.push_back(-depth * i / n);
  z.push_back(-depth);
  return z;
}

void ProgramWriter::emit(canon::OpKind op) {
  sink_.on(canon::Op{std::move(op), {}, origin_});
}

void ProgramWriter::begin(const std::string& title) {
  emit(canon::Comment{title});
  emit(canon::ToolChange{cut_.tool, cut_.tool_diameter});
  emit(canon::Spindle{cut_.rpm, canon::SpindleDir::Cw});
}

void ProgramWriter::end() {
  retract();
  emit(canon::Spindle{0.0, canon::SpindleDir::Off});
  emit(canon::ProgramEnd{});
}

void ProgramWriter::rapid(const Vec3& to) {
  emit(canon::Traverse{to});
  pos_ = to;
  known_ = true;
}

void ProgramWriter::retract() {
  if (known_ && pos_.z < cut_.safe_z) rapid({pos_.x, pos_.y, cut_.safe_z});
}

void ProgramWriter::rapid_over(Vec2 xy) {
  retract();
  if (!known_ || pos_.x != xy.x || pos_.y != xy.y) rapid({xy.x, xy.y, cut_.safe_z});
}

void ProgramWriter::plunge(double z) {
  emit(canon::Feed{{pos_.x, pos_.y, z}, cut_.plunge_feed});
  pos_.z = z;
}

void ProgramWriter::feed(const Vec3& to) {
  emit(canon::Feed{to, cut_.feed});
  pos_ = to;
}

void ProgramWriter::arc(Vec2 to, Vec2 center, int turn, double z) {
  emit(canon::Arc{{to.x, to.y, z}, {center.x, center.y, pos_.z}, {0, 0, 1}, turn, cut_.feed});
  pos_ = {to.x, to.y, z};
}

void ProgramWriter::path(const Path& p, double z) {
  for (const PathSegment& s : p.segs) {
    if (s.center) {
      arc(s.to, *s.center, s.turn, z);
    } else {
      feed({s.to.x, s.to.y, z});
    }
  }
}

}  // namespace usina::cam
