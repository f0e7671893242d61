#include "canon/limits.hpp"

#include <cmath>
#include <cstdlib>

#include <fmt/format.h>

namespace usina::canon {
namespace {

// Collects the first number out of range, naming it by the op and field.
class Checker {
 public:
  explicit Checker(const char* op) : op_(op) {}

  std::optional<std::string> problem;

  // `axis`, when not 0, names the coordinate after the field ("end X").
  // Hot (every op of every program): nothing is formatted unless a number
  // is out of range.
  void value(const char* field, double v, double max, const char* unit, char axis = 0) {
    if (problem || (std::fabs(v) <= max)) return;  // NaN fails the comparison
    out_of_range(field, v, max, unit, axis);
  }

  // Apart from value(), so value() stays small enough to be inlined.
  [[gnu::noinline]] void out_of_range(const char* field, double v, double max, const char* unit,
                                      char axis) {
    const std::string name = axis != 0 ? fmt::format("{} {}", field, axis) : std::string(field);
    if (!std::isfinite(v)) {
      problem = fmt::format("the {}'s {} ({}) is not a finite number", op_, name, v);
    } else {
      const std::string u = *unit != '\0' ? fmt::format(" {}", unit) : std::string();
      problem =
          fmt::format("the {}'s {} {:g}{} is beyond ±{}{}", op_, name, v, u, limit_text(max), u);
    }
  }

  void not_negative(const char* field, double v, double max, const char* unit) {
    value(field, v, max, unit);
    if (!problem && v < 0.0) problem = fmt::format("the {}'s {} {:g} is negative", op_, field, v);
  }

  void point(const char* field, const Vec3& p) {
    value(field, p.x, kMaxLength, "mm", 'X');
    value(field, p.y, kMaxLength, "mm", 'Y');
    value(field, p.z, kMaxLength, "mm", 'Z');
  }

  void point(const char* field, const Vec2& p) { point(field, Vec3{p.x, p.y, 0.0}); }

  void abc(const Abc& a) {
    value("A", a[0], kMaxAngle, "deg");
    value("B", a[1], kMaxAngle, "deg");
    value("C", a[2], kMaxAngle, "deg");
  }

  void feed(const std::optional<double>& f, const ProgrammedFeed& programmed) {
    if (f) rate("feed rate", *f);
    rate("programmed feed", programmed.value);
  }

  void rate(const char* field, double v) {
    if (problem) return;
    not_negative(field, v, kMaxFeed, "");
    if (!problem && v > 0.0 && v < kMinFeed) {
      problem = fmt::format("the {}'s {} {:g} is below {}, the smallest feed usina times", op_,
                            field, v, limit_text(kMinFeed));
    }
  }

 private:
  const char* op_;
};

struct Check {
  Checker& c;

  void operator()(const Traverse& t) const {
    c.point("end", t.to);
    c.abc(t.abc);
  }

  void operator()(const Feed& f) const {
    c.point("end", f.to);
    c.abc(f.abc);
    c.feed(f.f, f.programmed);
  }

  void operator()(const Arc& a) const {
    c.point("end", a.to);
    c.point("centre", a.center);
    c.value("normal", a.normal.x, 1.0 + 1e-9, "", 'X');
    c.value("normal", a.normal.y, 1.0 + 1e-9, "", 'Y');
    c.value("normal", a.normal.z, 1.0 + 1e-9, "", 'Z');
    c.abc(a.abc);
    c.feed(a.f, a.programmed);
    if (!c.problem && (a.turn == 0 || std::abs(a.turn) > kMaxTurns))
      c.problem = fmt::format("the arc's turn count {} is not within 1 and {}", a.turn, kMaxTurns);
  }

  void operator()(const Spline& s) const {
    c.point("end", s.to);
    for (const Vec3& p : s.points) {
      if (c.problem) return;
      c.point("point", p);
    }
    c.feed(s.f, s.programmed);
  }

  void operator()(const Probe& p) const {
    c.point("end", p.to);
    c.abc(p.abc);
  }

  void operator()(const Dwell& d) const { c.not_negative("time", d.s, kMaxDwell, "s"); }

  void operator()(const ToolChange& t) const {
    if (t.diameter) c.value("diameter", *t.diameter, kMaxLength, "mm");
  }

  void operator()(const Spindle& s) const {
    c.not_negative("speed", s.rpm, kMaxSpindle, "rev/min");
  }

  void operator()(const Hole& h) const {
    c.point("centre", h.at);
    c.value("diameter", h.diameter, kMaxLength, "mm");
    c.value("depth", h.depth, kMaxLength, "mm");
    if (h.f) c.rate("feed rate", *h.f);
  }

  void operator()(const Pocket& p) const {
    c.point("outline", p.outline.start);
    for (const OutlineSegment& s : p.outline.segs) {
      c.point("outline", s.to);
      if (s.center) c.point("outline centre", *s.center);
    }
    c.value("depth", p.depth, kMaxLength, "mm");
  }

  void operator()(const Coolant&) const {}

  void operator()(const Comment&) const {}

  void operator()(const ProgramEnd&) const {}

  void operator()(const MachineCode&) const {}

  void operator()(const PathMode& m) const {
    c.not_negative("tolerance", m.tolerance, kMaxLength, "mm");
    c.not_negative("naive CAM tolerance", m.naive_cam, kMaxLength, "mm");
  }
};

}  // namespace

std::string limit_text(double bound) {
  const double e = std::round(std::log10(bound));
  if (std::pow(10.0, e) == bound) return fmt::format("1e{}", static_cast<int>(e));
  return fmt::format("{:g}", bound);
}

tl::expected<void, std::string> range_problem(const OpKind& op) {
  Checker c(op_name(op));
  std::visit(Check{c}, op);
  if (c.problem) return tl::unexpected(std::move(*c.problem));
  return {};
}

tl::expected<void, std::string> range_problem(const Traverse& move) {
  Checker c("traverse");
  Check{c}(move);
  if (c.problem) return tl::unexpected(std::move(*c.problem));
  return {};
}

tl::expected<void, std::string> range_problem(const Feed& move) {
  Checker c("feed");
  Check{c}(move);
  if (c.problem) return tl::unexpected(std::move(*c.problem));
  return {};
}

tl::expected<void, std::string> check_length(const char* what, double mm) {
  if (!std::isfinite(mm))
    return tl::unexpected(fmt::format("{} ({}) is not a finite number", what, mm));
  if (std::fabs(mm) > kMaxLength)
    return tl::unexpected(
        fmt::format("{} {:g} mm is beyond ±{} mm", what, mm, limit_text(kMaxLength)));
  return {};
}

tl::expected<void, std::string> check_feed(const char* what, double rate) {
  if (!std::isfinite(rate))
    return tl::unexpected(fmt::format("{} ({}) is not a finite number", what, rate));
  if (std::fabs(rate) > kMaxFeed) {
    return tl::unexpected(fmt::format("{} {:g} is beyond {}", what, rate, limit_text(kMaxFeed)));
  }
  if (rate != 0.0 && std::fabs(rate) < kMinFeed) {
    return tl::unexpected(fmt::format("{} {:g} is below {}, the smallest feed usina times", what,
                                      rate, limit_text(kMinFeed)));
  }
  return {};
}

}  // namespace usina::canon
