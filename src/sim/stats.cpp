#include "sim/stats.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "canon/bare_hole.hpp"
#include "canon/limits.hpp"
#include "sim/planner_models.hpp"

namespace usina::sim {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

Axes6 axes_of(const Vec3& p, const canon::Abc& abc) {
  return {p.x, p.y, p.z, abc[0], abc[1], abc[2]};
}

Vec3 xyz(const Axes6& a) {
  return {a[0], a[1], a[2]};
}

// Path length: the X Y Z distance, or for a move of rotary axes only their
// distance in degrees (LinuxCNC's rule for the feed of such moves).
double path_length(const Axes6& from, const Axes6& to) {
  const double linear = distance(xyz(from), xyz(to));
  if (linear > 0.0) return linear;
  return std::hypot(to[3] - from[3], to[4] - from[4], to[5] - from[5]);
}

Vec3 direction(const Axes6& from, const Axes6& to) {
  const Vec3 d = xyz(to) - xyz(from);
  const double n = norm(d);
  return n > 0.0 ? d / n : Vec3{};
}

}  // namespace

MachineProfile default_machine_profile() {
  MachineProfile m;
  m.name = "default (generic 3-axis mill, no travel limits)";
  for (std::size_t i = 0; i < 3; ++i) {
    AxisLimits& a = m.axes[i];
    a.present = true;
    a.min = -kInf;
    a.max = kInf;
    a.rapid = 10000.0;
    a.max_feed = 5000.0;
    a.accel = 500.0;
  }
  m.spindle_max_rpm = 24000.0;
  m.spindle_accel_time = 2.0;
  m.tool_change_time = 10.0;
  return m;
}

void Counts::add(const Counts& c) {
  rapids += c.rapids;
  feeds += c.feeds;
  arcs += c.arcs;
  splines += c.splines;
  probes += c.probes;
  holes += c.holes;
  tool_changes += c.tool_changes;
  dwells += c.dwells;
}

StatsSink::StatsSink(const MachineProfile& machine, StatsOptions options,
                     core::DiagnosticSink& diags)
    : machine_(machine),
      options_(options),
      diags_(diags),
      checks_(machine_, options.stock_top, options.work_zero, options.max_reports_per_check, diags),
      planner_(make_planner(machine, options.lookahead)) {
  tools_.emplace_back();
  slot_of_tool_[0] = 0;
}

void StatsSink::observe(TimeObserver observer) {
  if (!observer) {
    planner_->observe({});
    return;
  }
  // A wait belongs to the op that asked for it: the one being taken.
  planner_->observe([this, observer = std::move(observer)](std::uint64_t op, double s) {
    observer(op == kWaitOp ? op_ : op, s);
  });
}

void StatsSink::on(const canon::Op& op) {
  ++op_;
  // Every front end keeps canon's range (canon/limits.hpp); a back end that
  // sums times checks it again, so no NaN or infinity enters a total.
  if (auto in_range = canon::check_range(op.kind); !in_range) {
    if (!refused_) {
      diags_.report({core::Code::ValueOutOfRange, core::Severity::Error, op.src,
                     fmt::format("{}: the op is left out of the figures", in_range.error())});
    }
    refused_ = true;
    return;
  }
  std::visit(
      [&](const auto& k) {
        using T = std::decay_t<decltype(k)>;
        if constexpr (std::is_same_v<T, canon::Traverse>) {
          traverse(op, k);
        } else if constexpr (std::is_same_v<T, canon::Feed>) {
          feed_in_force_ = k;
          feed(op, k.to, k.abc, k.f, k.programmed);
        } else if constexpr (std::is_same_v<T, canon::Arc>) {
          arc(op, k);
        } else if constexpr (std::is_same_v<T, canon::Spline>) {
          spline(op, k);
        } else if constexpr (std::is_same_v<T, canon::Probe>) {
          probe(op, k);
        } else if constexpr (std::is_same_v<T, canon::Dwell>) {
          ++tool().counts.dwells;
          planner_->wait(k.s, account(Other));
        } else if constexpr (std::is_same_v<T, canon::ToolChange>) {
          tool_change(k);
        } else if constexpr (std::is_same_v<T, canon::Spindle>) {
          spindle(k);
        } else if constexpr (std::is_same_v<T, canon::Hole>) {
          ++tool().counts.holes;
          const canon::Abc abc{pos_[3], pos_[4], pos_[5]};
          const canon::Spindle running{spindle_rpm_, spindle_dir_};  // restarted after a G86
          for (const canon::Op& m :
               canon::bare_hole_moves(op, k, xyz(pos_), abc, feed_in_force_, running))
            on(m);
        } else if constexpr (std::is_same_v<T, canon::ProgramEnd>) {
          planner_->stop();
        } else if constexpr (std::is_same_v<T, canon::PathMode>) {
          planner_->path_mode(k);
        }
      },
      op.kind);
}

void StatsSink::finish() {
  planner_->stop();
  if (planner_->untimed() > 0 && !reported_untimed_) {
    reported_untimed_ = true;
    diags_.report({core::Code::ValueOutOfRange,
                   core::Severity::Error,
                   {},
                   fmt::format("{} moves could not be timed (their time came out infinite or "
                               "undefined): check the machine profile's accelerations, jerks "
                               "and rates; the times shown leave them out",
                               planner_->untimed())});
  }
}

// [times] block: a control that processes a block in t s cannot run blocks
// shorter than t, so a block's speed is at most its length / t.
double StatsSink::block_limit(double length, double cruise) const {
  if (machine_.block_time <= 0.0) return cruise;
  return std::min(cruise, length / machine_.block_time);
}

void StatsSink::moved_to(const Axes6& to) {
  pos_ = to;
}

StatsSink::Line StatsSink::line_to(const Axes6& to) const {
  const double length = path_length(pos_, to);
  const AxisShare share = straight_share(pos_, to, length);
  return {to, length, share, path_rates(machine_, share)};
}

PlannedMove StatsSink::straight_move(const Line& line, double cruise, Kind kind) const {
  PlannedMove m;
  m.length = line.length;
  m.start_dir = m.end_dir = direction(pos_, line.to);
  m.cruise = block_limit(line.length, cruise);
  m.kin = {line.rates.accel, line.rates.jerk};
  m.account = account(kind);
  m.op = op_;
  m.max_speed = line.rates.rapid;
  m.rapid = kind == Rapid;
  return m;
}

double StatsSink::straight(const Line& line, double cruise, Kind kind) {
  const PlannedMove m = straight_move(line, cruise, kind);
  planner_->add(m);
  return m.length;
}

void StatsSink::traverse(const canon::Op& op, const canon::Traverse& t) {
  const Axes6 to = axes_of(t.to, t.abc);
  const Vec3 from = xyz(pos_);
  Box box;
  box.add(from);
  box.add(t.to);
  checks_.travel(op, box.lo, box.hi, to);
  checks_.rapid(op, from, t.to);
  const Line line = line_to(to);
  const double cruise = line.rates.rapid;
  ToolStats& ts = tool();
  ts.rapid_mm += straight(line, cruise, Rapid);
  ++ts.counts.rapids;
  ts.bounds.add(box);
  moved_to(to);
}

double StatsSink::feed_speed(const canon::Op& op, const AxisShare& share, double rate) {
  int axis = -1;
  const double limit = along_path(machine_, share, AxisRate::MaxFeed, &axis);  // mm/s
  return feed_speed(op, limit, axis, rate);
}

// The speed a feed move runs at (mm/s): its rate within `limit`, the most
// the axes allow, which `limiting_axis` sets.
double StatsSink::feed_speed(const canon::Op& op, double limit, int limiting_axis, double rate) {
  const bool has_rate = rate > 0.0;
  checks_.feed(op, has_rate, spindle_dir_ != canon::SpindleDir::Off);
  if (!has_rate) return limit;
  tool().feed.add(rate);
  last_feed_ = rate;
  checks_.feed_limit(op, rate, limit * 60.0, limiting_axis);
  return std::min(rate / 60.0, limit);
}

// The mm/min a move runs at: its F, or what G93 (the move takes 1/F
// minutes, whatever its length) or G95 (F mm a spindle revolution) make of
// it; 0 when it has none.
double StatsSink::rate_of(std::optional<double> f, const canon::ProgrammedFeed& programmed,
                          double length) const {
  using Mode = canon::ProgrammedFeed::Mode;
  if (f) return *f;
  if (programmed.value <= 0.0) return 0.0;
  if (programmed.mode == Mode::InverseTime && length > 0.0) return length * programmed.value;
  if (programmed.mode == Mode::PerRevolution && spindle_dir_ != canon::SpindleDir::Off &&
      spindle_rpm_ > 0.0) {
    return programmed.value * spindle_rpm_;
  }
  return 0.0;
}

void StatsSink::feed(const canon::Op& op, const Vec3& to_xyz, const canon::Abc& abc,
                     std::optional<double> f, const canon::ProgrammedFeed& programmed) {
  const Axes6 to = axes_of(to_xyz, abc);
  Box box;
  box.add(xyz(pos_));
  box.add(to_xyz);
  checks_.travel(op, box.lo, box.hi, to);
  const Line line = line_to(to);
  const double cruise = feed_speed(op, line.rates.max_feed, line.rates.max_feed_axis,
                                   rate_of(f, programmed, line.length));
  ToolStats& ts = tool();
  ts.cutting_mm += straight(line, cruise, Cutting);
  ++ts.counts.feeds;
  ts.bounds.add(box);
  moved_to(to);
}

void StatsSink::arc(const canon::Op& op, const canon::Arc& a) {
  const std::optional<ArcPath> path = arc_path(xyz(pos_), a);
  if (!path) {
    // No radius: the control moves straight to the end.
    feed(op, a.to, a.abc, a.f, a.programmed);
    --tool().counts.feeds;
    ++tool().counts.arcs;
    return;
  }
  const Axes6 to = axes_of(a.to, a.abc);
  Box box;
  arc_extent(*path, box.lo, box.hi);
  checks_.travel(op, box.lo, box.hi, to);
  // Per-axis share: an in-plane axis moves at most as fast as the tangent.
  AxisShare share;
  const double turning = path->radius * std::abs(path->sweep) / path->length;
  double centripetal = kInf;
  for (std::size_t i = 0; i < 3; ++i) {
    const int ax = static_cast<int>(i);
    const double in_plane = std::hypot(path->u[ax], path->v[ax]);
    share.share[i] =
        in_plane * turning + std::abs(path->normal[ax]) * std::abs(path->axial) / path->length;
    if (in_plane > 1e-9 && machine_.axes[i].present) {
      centripetal = std::min(centripetal, machine_.axes[i].accel / in_plane);
    }
  }
  const double rate = rate_of(a.f, a.programmed, path->length);
  double cruise = feed_speed(op, share, rate);
  const double arc_limit = std::sqrt(centripetal * path->radius);  // v²/r ≤ a
  if (rate > 0.0) {
    checks_.arc_feed(op, path->radius, cruise * 60.0, arc_limit * 60.0, centripetal);
  }
  const double uncapped = cruise;
  cruise = std::min(cruise, arc_limit);
  PlannedMove m;
  m.length = path->length;
  m.start_dir = path->start_tangent;
  m.end_dir = path->end_tangent;
  m.cruise = block_limit(path->length, cruise);
  m.kin = {along_path(machine_, share, AxisRate::Accel),
           along_path(machine_, share, AxisRate::Jerk)};
  m.account = account(Cutting);
  m.op = op_;
  m.radius = path->radius;
  m.sweep = path->sweep;
  m.normal = path->normal;
  m.axial = path->axial;
  m.helix = std::abs(path->axial) > 1e-9;
  m.uncapped = block_limit(path->length, uncapped);
  m.max_speed = along_path(machine_, share, AxisRate::Rapid);
  planner_->add(m);
  ToolStats& ts = tool();
  ts.cutting_mm += path->length;
  ++ts.counts.arcs;
  ts.bounds.add(box);
  moved_to(to);
}

void StatsSink::spline(const canon::Op& op, const canon::Spline& s) {
  Box box;
  box.add(xyz(pos_));
  double length = 0.0;
  Vec3 prev = xyz(pos_);
  for (const Vec3& p : s.points) {
    box.add(p);
    length += distance(prev, p);
    prev = p;
  }
  const Axes6 to{s.to.x, s.to.y, s.to.z, pos_[3], pos_[4], pos_[5]};
  checks_.travel(op, box.lo, box.hi, to);
  // The spline's feed is checked once, along its chord.
  const double cruise = feed_speed(op, straight_share(pos_, to, path_length(pos_, to)),
                                   rate_of(s.f, s.programmed, length));
  // A spline is one block: the block time limits the whole curve's speed.
  const double spline_cruise = block_limit(length, cruise);
  for (const Vec3& p : s.points) {
    const Axes6 next{p.x, p.y, p.z, pos_[3], pos_[4], pos_[5]};
    const double seg = path_length(pos_, next);
    const double seg_cruise = std::min(
        spline_cruise, along_path(machine_, straight_share(pos_, next, seg), AxisRate::MaxFeed));
    PlannedMove m;
    const AxisShare share = straight_share(pos_, next, seg);
    m.length = seg;
    m.start_dir = m.end_dir = direction(pos_, next);
    m.cruise = seg_cruise;
    m.kin = {along_path(machine_, share, AxisRate::Accel),
             along_path(machine_, share, AxisRate::Jerk)};
    m.account = account(Cutting);
    m.op = op_;
    m.max_speed = along_path(machine_, share, AxisRate::Rapid);
    planner_->add(m);
    pos_ = next;
  }
  ToolStats& ts = tool();
  ts.cutting_mm += length;
  ++ts.counts.splines;
  ts.bounds.add(box);
  moved_to(to);
}

// A probe move runs at the feed last programmed (G38 uses F) and stops where
// the probe trips; taken as reaching its end. Its time counts as "other".
void StatsSink::probe(const canon::Op& op, const canon::Probe& p) {
  const Axes6 to = axes_of(p.to, p.abc);
  Box box;
  box.add(xyz(pos_));
  box.add(p.to);
  checks_.travel(op, box.lo, box.hi, to);
  const Line line = line_to(to);
  const double limit = line.rates.max_feed;
  const double cruise = last_feed_ ? std::min(*last_feed_ / 60.0, limit) : limit;
  straight(line, cruise, Other);
  planner_->stop();
  ToolStats& ts = tool();
  ++ts.counts.probes;
  ts.bounds.add(box);
  moved_to(to);
}

// Spindle start-up: the profile's accel_time takes the spindle from stop to
// max_rpm, so a change of speed takes accel_time × |Δrpm| / max_rpm (a
// reversal: down to 0 and up again). The motion waits for it (M3/M4 are
// synchronised with motion); M5 does not wait for the spindle to stop.
void StatsSink::spindle(const canon::Spindle& s) {
  const bool running = spindle_dir_ != canon::SpindleDir::Off;
  const bool starts = s.dir != canon::SpindleDir::Off;
  double change = 0.0;
  if (starts) {
    const double from = !running ? 0.0 : spindle_rpm_;
    change = (running && s.dir != spindle_dir_) ? from + s.rpm : std::abs(s.rpm - from);
    if (s.rpm > 0.0) tool().rpm.add(s.rpm);
  }
  const double full = machine_.spindle_max_rpm > 0.0 ? machine_.spindle_max_rpm : s.rpm;
  const double seconds =
      full > 0.0 ? machine_.spindle_accel_time * std::min(change / full, 2.0) : 0.0;
  planner_->wait(seconds, account(Other));
  spindle_dir_ = s.dir;
  spindle_rpm_ = starts ? s.rpm : 0.0;
}

void StatsSink::tool_change(const canon::ToolChange& t) {
  auto [it, added] = slot_of_tool_.try_emplace(t.tool, tools_.size());
  if (added) {
    tools_.emplace_back();
    tools_.back().tool = t.tool;
  }
  planner_->stop();  // the times so far belong to the tool before
  tool_slot_ = it->second;
  ++tool().counts.tool_changes;
  planner_->wait(machine_.tool_change_time, account(Other));
}

StatsReport StatsSink::report() const {
  StatsReport r;
  const auto& times = planner_->accounts();
  for (std::size_t slot = 0; slot < tools_.size(); ++slot) {
    ToolStats t = tools_[slot];
    const auto take = [&](Kind k, double& into) {
      const std::size_t id = slot * 3 + k;
      if (id >= times.size()) return;
      into = times[id].lookahead_s;
      t.exact_stop_s += times[id].exact_stop_s;
    };
    take(Cutting, t.cutting_s);
    take(Rapid, t.rapid_s);
    take(Other, t.other_s);
    const bool idle = t.total_s() == 0.0 && t.counts.moves() == 0 && t.counts.tool_changes == 0 &&
                      t.counts.holes == 0;
    if (!idle) r.tools.push_back(t);
  }
  ToolStats& all = r.total;
  all.tool = -1;
  for (const ToolStats& t : r.tools) {
    all.cutting_s += t.cutting_s;
    all.rapid_s += t.rapid_s;
    all.other_s += t.other_s;
    all.exact_stop_s += t.exact_stop_s;
    all.cutting_mm += t.cutting_mm;
    all.rapid_mm += t.rapid_mm;
    all.counts.add(t.counts);
    all.bounds.add(t.bounds);
    all.feed.add(t.feed);
    all.rpm.add(t.rpm);
  }
  r.cost = all.total_s() / 3600.0 * machine_.cost_per_hour;
  r.checks = checks_.counts();
  return r;
}

}  // namespace usina::sim
