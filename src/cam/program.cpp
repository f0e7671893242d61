#include "cam/program.hpp"

#include <cmath>

#include <fmt/format.h>

namespace usina::cam {

bool fail(core::DiagnosticSink& diags, core::Code code, std::string message) {
  diags.report({code, core::Severity::Error, {}, std::move(message)});
  return false;
}

bool check_cutting(const Cutting& c, core::DiagnosticSink& diags) {
  bool ok =
      check_range("the tool diameter (--tool-diameter)", c.tool_diameter, kToolDiameter, diags);
  ok = check_range("the feed (--feed)", c.feed, kFeed, diags) && ok;
  ok = check_range("the plunge feed (--plunge-feed)", c.plunge_feed, kFeed, diags) && ok;
  ok = check_range("the spindle speed (--rpm)", c.rpm, kSpindle, diags) && ok;
  ok = check_range("the safe Z (--safe-z)", c.safe_z, kLength, diags) && ok;
  ok = check_range("the tool number (--tool)", c.tool, kToolNumber, diags) && ok;
  ok = check_range("the limit on moves (--max-moves)", c.max_moves, kMaxMovesRange, diags) && ok;
  return ok;
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
