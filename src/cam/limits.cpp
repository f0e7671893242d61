#include "cam/limits.hpp"

#include <cmath>
#include <string>

#include <fmt/format.h>

#include "cam/program.hpp"

namespace usina::cam {
namespace {

// 1000000 as "1000000" (not 1e+06), 0.001 as "0.001", 1e-300 as "1e-300":
// a number as a user writes it.
std::string number_text(double v) {
  if (std::isfinite(v) && v == std::floor(v) && std::fabs(v) < 1e12) {
    return fmt::format("{:.0f}", v);
  }
  return fmt::format("{:g}", v);
}

// A size in bytes for a message: "about 58 GB".
std::string size_text(double bytes) {
  constexpr const char* kUnits[] = {"bytes", "kB", "MB", "GB", "TB"};
  std::size_t u = 0;
  while (bytes >= 1000.0 && u + 1 < std::size(kUnits)) {
    bytes /= 1000.0;
    ++u;
  }
  return fmt::format("{:.3g} {}", bytes, kUnits[u]);
}

}  // namespace

std::string count_text(double n) {
  if (!(n < 1e15)) return fmt::format("{:.3g}", n);
  const std::string digits = fmt::format("{:.0f}", n);
  std::string out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

bool check_range(std::string_view what, double value, const Range& r, core::DiagnosticSink& diags) {
  const bool above_min = r.min_included ? value >= r.min : value > r.min;
  if (std::isfinite(value) && above_min && value <= r.max) return true;
  const std::string unit = r.unit.empty() ? "" : fmt::format(" {}", r.unit);
  const std::string range =
      r.min_included
          ? fmt::format("from {} to {}{}", number_text(r.min), number_text(r.max), unit)
          : fmt::format("above {} and at most {}{}", number_text(r.min), number_text(r.max), unit);
  return fail(diags, core::Code::GenBadValue,
              fmt::format("{} is {}{}; give a number {}", what, number_text(value), unit, range));
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
              fmt::format("a depth of {:g} mm in steps of {:g} mm makes more than {} passes; "
                          "give a larger step down",
                          depth, step, kMaxPasses));
}

double path_moves(const std::vector<Path>& paths) {
  double n = 0;
  for (const Path& p : paths)
    n += static_cast<double>(p.segs.size()) + 3;
  return n;
}

bool check_work(std::string_view what, double moves, double max_moves, std::string_view remedy,
                core::DiagnosticSink& diags) {
  if (moves <= max_moves) return true;
  return fail(diags, core::Code::GenTooMuchWork,
              fmt::format("{} would be about {} moves (about {} of G-code), more than the limit "
                          "of {}; {}, or raise the limit with --max-moves",
                          what, count_text(moves), size_text(moves * kBytesPerMove),
                          count_text(max_moves), remedy));
}

}  // namespace usina::cam
