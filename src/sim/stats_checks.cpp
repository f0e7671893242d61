#include "sim/stats_checks.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace usina::sim {

namespace {

constexpr double kTolerance = 1e-6;  // mm (DESIGN.md: geometry checks)

}  // namespace

char axis_letter(int axis) {
  return "XYZABC"[axis >= 0 && axis < 6 ? axis : 0];
}

StatsChecks::StatsChecks(const MachineProfile& machine, std::optional<double> stock_top,
                         std::optional<Vec3> work_zero, std::size_t cap,
                         core::DiagnosticSink& diags)
    : machine_(machine), stock_top_(stock_top), work_zero_(work_zero), cap_(cap), diags_(diags) {}

void StatsChecks::flag(core::Code code, const canon::Op& op, bool first_of_run,
                       const std::string& message) {
  ++counts_[code];
  if (!first_of_run) return;
  std::size_t& shown = shown_[code];
  if (shown >= cap_) return;
  ++shown;
  diags_.report({code, core::Severity::Warning, op.src, message});
}

void StatsChecks::extent(const canon::Op& op, int i, double low, double high) {
  const auto k = static_cast<std::size_t>(i);
  span_lo_[k] = spanned_ ? std::min(span_lo_[k], low) : low;
  span_hi_[k] = spanned_ ? std::max(span_hi_[k], high) : high;
  const AxisLimits& a = machine_.axes[k];
  if (too_long_[k] || span_hi_[k] - span_lo_[k] <= a.max - a.min + kTolerance) return;
  span_too_long(op, i);
}

[[gnu::noinline]] void StatsChecks::span_too_long(const canon::Op& op, int i) {
  const auto k = static_cast<std::size_t>(i);
  const AxisLimits& a = machine_.axes[k];
  too_long_[k] = true;
  flag(core::Code::OverTravel, op, true,
       fmt::format("{} spans {:.3f} mm (from {:.3f} to {:.3f}), more than the {:.3f} mm the axis "
                   "travels; give the work zero (--work-zero or --var-file) to check the limits",
                   axis_letter(i), span_hi_[k] - span_lo_[k], span_lo_[k], span_hi_[k],
                   a.max - a.min));
}

void StatsChecks::travel(const canon::Op& op, const Vec3& lo, const Vec3& hi, const Axes6& end) {
  // Without a work zero, the linear axes' spans are what can be checked;
  // their limits only with one. Two loops, not one test of both a turn:
  // every move of `stats` comes here (issue 19).
  int first_limited = 0;
  if (!work_zero_) {
    for (int i = 0; i < 3; ++i) {
      if (machine_.axes[static_cast<std::size_t>(i)].present) extent(op, i, lo[i], hi[i]);
    }
    first_limited = 3;
  }
  for (int i = first_limited; i < 6; ++i) {
    if (machine_.axes[static_cast<std::size_t>(i)].present) limits(op, i, lo, hi, end);
  }
  spanned_ = true;
}

void StatsChecks::limits(const canon::Op& op, int i, const Vec3& lo, const Vec3& hi,
                         const Axes6& end) {
  const AxisLimits& a = machine_.axes[static_cast<std::size_t>(i)];
  const double shift = i < 3 ? (*work_zero_)[i] : 0.0;
  const double low = i < 3 ? lo[i] + shift : end[static_cast<std::size_t>(i)];
  const double high = i < 3 ? hi[i] + shift : end[static_cast<std::size_t>(i)];
  const char* unit = i < 3 ? "mm" : "deg";
  auto& out = outside_[static_cast<std::size_t>(i)];
  const bool below = low < a.min - kTolerance;
  const bool above = high > a.max + kTolerance;
  if (below) {
    flag(core::Code::OverTravel, op, !out[0],
         fmt::format("{} goes to {:.3f} {}, {:.3f} {} below its travel limit {:.3f}",
                     axis_letter(i), low, unit, a.min - low, unit, a.min));
  }
  if (above) {
    flag(core::Code::OverTravel, op, !out[1],
         fmt::format("{} goes to {:.3f} {}, {:.3f} {} above its travel limit {:.3f}",
                     axis_letter(i), high, unit, high - a.max, unit, a.max));
  }
  // The excursion lasts until a move ends back inside the limits.
  const double at = end[static_cast<std::size_t>(i)] + shift;
  out = {at<a.min - kTolerance, at> a.max + kTolerance};
}

void StatsChecks::feed(const canon::Op& op, bool has_rate, bool spindle_running) {
  if (!has_rate) {
    flag(core::Code::FeedWithoutRate, op, !in_no_rate_run_,
         "feed move without a feed rate (per revolution with the spindle stopped): "
         "timed at the axes' max feed, so the time is a lower bound");
  }
  in_no_rate_run_ = !has_rate;
  if (!spindle_running) {
    flag(core::Code::FeedSpindleStopped, op, !in_stopped_run_,
         "feed move with the spindle stopped (no M3/M4 since the start, M5 or M6)");
  }
  in_stopped_run_ = !spindle_running;
}

void StatsChecks::rapid(const canon::Op& op, const Vec3& from, const Vec3& to) {
  if (!stock_top_) return;
  const double top = *stock_top_;
  const bool ends_in = to.z < top - kTolerance;
  const bool across =
      from.z < top - kTolerance && std::hypot(to.x - from.x, to.y - from.y) > kTolerance;
  const bool into = ends_in || across;
  if (into) {
    flag(core::Code::RapidIntoStock, op, !in_stock_run_,
         ends_in ? fmt::format("rapid move down to Z{:.3f}, {:.3f} mm below the stock top "
                               "Z{:.3f}: it would cut at rapid speed",
                               to.z, top - to.z, top)
                 : fmt::format("rapid move across X/Y at Z{:.3f}, {:.3f} mm below the stock "
                               "top Z{:.3f}: it would cut at rapid speed",
                               from.z, top - from.z, top));
  }
  in_stock_run_ = into;
}

void StatsChecks::arc_feed(const canon::Op& op, double radius, double feed, double allowed,
                           double accel) {
  const bool reduced = allowed < feed * (1.0 - 1e-9);
  if (reduced) {
    flag(core::Code::ArcFeedReduced, op, !in_arc_run_,
         fmt::format("arc of radius {:.3f} mm too tight for F{:g}: at {:g} mm/s² the centripetal "
                     "acceleration v²/r allows {:.1f} mm/min, so the feed is reduced by {:.1f} %",
                     radius, feed, accel, allowed, 100.0 * (1.0 - allowed / feed)));
  }
  in_arc_run_ = reduced;
}

void StatsChecks::feed_limit(const canon::Op& op, double feed, double allowed, int axis) {
  const bool clamped = allowed < feed * (1.0 - 1e-9);
  if (clamped) {
    flag(core::Code::FeedClamped, op, !in_clamp_run_,
         fmt::format("F{:g} is above the max feed of axis {} along this move: runs at {:.1f} "
                     "mm/min",
                     feed, axis_letter(axis), allowed));
  }
  in_clamp_run_ = clamped;
}

}  // namespace usina::sim
