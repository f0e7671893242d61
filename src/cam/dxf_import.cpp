#include "cam/dxf_import.hpp"

#include <dl_creationadapter.h>
#include <dl_dxf.h>
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <istream>
#include <numbers>
#include <sstream>
#include <system_error>

#include <fmt/format.h>
#include <sys/stat.h>

#include "cam/dxf_groups.hpp"
#include "cam/spline_approx.hpp"

namespace usina::cam {
namespace {

bool same_layer(const std::string& a, const std::string& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](char x, char y) {
    return std::tolower(static_cast<unsigned char>(x)) ==
           std::tolower(static_cast<unsigned char>(y));
  });
}

bool within_range(Vec2 v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::fabs(v.x) <= kMaxDrawingCoordinate &&
         std::fabs(v.y) <= kMaxDrawingCoordinate;
}

double radians(double degrees) {
  return degrees * std::numbers::pi / 180.0;
}

// Collects entities. ARC, CIRCLE and LWPOLYLINE are in the entity's object
// coordinate system; the only one a flat drawing uses besides the world's is
// the mirrored one, extrusion (0, 0, −1), whose X axis is the world's −X
// (DXF reference, "Arbitrary Axis Algorithm"), so its arcs turn clockwise.
class Collector final : public DL_CreationAdapter {
 public:
  Collector(const DxfOptions& o, std::string name, core::DiagnosticSink& d)
      : options_(o), name_(std::move(name)), diags_(d) {}

  std::vector<Path> paths;
  int on_layer = 0;  // entities seen on the selected layer, unsupported ones included

  void addBlock(const DL_BlockData&) override { in_block_ = true; }

  void endBlock() override { in_block_ = false; }

  void addLine(const DL_LineData& d) override {
    if (!begin_entity()) return;
    keep({{d.x1, d.y1}, {{{d.x2, d.y2}, std::nullopt, 0}}, false});
  }

  void addArc(const DL_ArcData& d) override {
    if (!begin_entity()) return;
    const Vec2 c = ocs({d.cx, d.cy});
    const Vec2 a = ocs({d.cx + d.radius * std::cos(radians(d.angle1)),
                        d.cy + d.radius * std::sin(radians(d.angle1))});
    const Vec2 b = ocs({d.cx + d.radius * std::cos(radians(d.angle2)),
                        d.cy + d.radius * std::sin(radians(d.angle2))});
    if (!(d.radius > 0.0)) return warn("an ARC of no radius; left out");
    keep({a, {{b, c, mirrored() ? -1 : 1}}, false});
  }

  void addCircle(const DL_CircleData& d) override {
    if (!begin_entity()) return;
    const Vec2 c = ocs({d.cx, d.cy});
    const Vec2 a = ocs({d.cx + d.radius, d.cy});
    if (!(d.radius > 0.0)) return warn("a CIRCLE of no radius; left out");
    keep({a, {{a, c, mirrored() ? -1 : 1}}, true});
  }

  // LWPOLYLINE and POLYLINE: vertices follow, each bulge belongs to the
  // segment that starts at its vertex; flag 1 closes the polyline.
  void addPolyline(const DL_PolylineData& d) override {
    if (!begin_entity()) return;
    poly_ = Poly{};
    poly_->closed = (d.flags & 1) != 0;
    poly_->mirrored = mirrored();
  }

  void addVertex(const DL_VertexData& d) override {
    if (poly_) poly_->vertices.push_back({d.x, d.y, d.bulge});
  }

  void endSequence() override { flush(); }

  void addSpline(const DL_SplineData& d) override {
    if (!begin_entity()) return;
    spline_ = SplineData{};
    spline_->degree = static_cast<int>(d.degree);
    spline_->closed = (d.flags & 1) != 0;
  }

  void addControlPoint(const DL_ControlPointData& d) override {
    if (spline_) spline_->control.push_back({{d.x, d.y}, d.w});
  }

  void addKnot(const DL_KnotData& d) override {
    if (spline_) spline_->knots.push_back(d.k);
  }

  void addFitPoint(const DL_FitPointData& d) override {
    if (spline_) spline_->fit.push_back({d.x, d.y});
  }

  void addPoint(const DL_PointData&) override { unsupported("POINT"); }

  void addEllipse(const DL_EllipseData&) override { unsupported("ELLIPSE"); }

  void addXLine(const DL_XLineData&) override { unsupported("XLINE"); }

  void addRay(const DL_RayData&) override { unsupported("RAY"); }

  void addInsert(const DL_InsertData&) override { unsupported("INSERT (explode the block)"); }

  void addText(const DL_TextData&) override { unsupported("TEXT (use usina gen engrave)"); }

  void addMText(const DL_MTextData&) override { unsupported("MTEXT (use usina gen engrave)"); }

  void addHatch(const DL_HatchData&) override { unsupported("HATCH"); }

  void addSolid(const DL_SolidData&) override { unsupported("SOLID"); }

  void addTrace(const DL_TraceData&) override { unsupported("TRACE"); }

  void add3dFace(const DL_3dFaceData&) override { unsupported("3DFACE"); }

  void addLeader(const DL_LeaderData&) override { unsupported("LEADER"); }

  void addImage(const DL_ImageData&) override { unsupported("IMAGE"); }

  // Ends whatever entity is still open (a SPLINE has no end marker).
  void flush() {
    if (poly_) finish_polyline();
    if (spline_) finish_spline();
  }

 private:
  struct Vertex {
    double x, y, bulge;
  };

  struct Poly {
    std::vector<Vertex> vertices;
    bool closed = false;
    bool mirrored = false;
  };

  struct SplineData {
    int degree = 0;
    bool closed = false;
    std::vector<WeightedPoint> control;
    std::vector<double> knots;
    std::vector<Vec2> fit;
  };

  bool mirrored() { return getExtrusion()->getDirection()[2] < 0.0; }

  Vec2 ocs(Vec2 p) { return mirrored() ? Vec2{-p.x, p.y} : p; }

  // True when the entity starting now is to be read.
  bool begin_entity() {
    flush();
    ++entity_;
    if (in_block_) return false;
    if (options_.layer && !same_layer(getAttributes().getLayer(), *options_.layer)) return false;
    ++on_layer;
    return true;
  }

  void warn(std::string message) {
    diags_.report({core::Code::DxfUnsupportedEntity,
                   core::Severity::Warning,
                   {},
                   fmt::format("{}: entity {}: {}", name_, entity_, message)});
  }

  void unsupported(const char* what) {
    if (!begin_entity()) return;
    warn(fmt::format("{} on layer \"{}\" is not a contour usina can cut; left out", what,
                     getAttributes().getLayer()));
  }

  void finish_polyline();
  void finish_spline();
  std::string spline_beyond_limits(const SplineData& s);

  // Takes the entity when every coordinate is a number within
  // kMaxDrawingCoordinate, so that no later stage (Clipper's integer range,
  // arc linearisation) meets a value it cannot take.
  void keep(Path p) {
    bool good = within_range(p.start);
    for (const PathSegment& seg : p.segs)
      good = good && within_range(seg.to) && (!seg.center || within_range(*seg.center));
    if (!good) {
      return warn(fmt::format("a coordinate is not a number or beyond ±{:g} mm; left out",
                              kMaxDrawingCoordinate));
    }
    paths.push_back(std::move(p));
  }

  const DxfOptions& options_;
  std::string name_;
  core::DiagnosticSink& diags_;
  bool in_block_ = false;
  int entity_ = 0;
  std::optional<Poly> poly_;
  std::optional<SplineData> spline_;
  double spline_work_ = 0;  // (control points × degree)² of the splines so far
  std::size_t spline_points_ = 0;
};

void Collector::finish_polyline() {
  Poly p = std::move(*poly_);
  poly_.reset();
  if (p.vertices.size() < 2) {
    warn(fmt::format("a polyline with {} vertex is not a path; left out", p.vertices.size()));
    return;
  }
  const double sign = p.mirrored ? -1.0 : 1.0;  // mirroring reverses every bulge
  auto at = [&](std::size_t i) { return Vec2{sign * p.vertices[i].x, p.vertices[i].y}; };
  Path path{at(0), {}, p.closed};
  const std::size_t n = p.vertices.size();
  const std::size_t segments = p.closed ? n : n - 1;
  for (std::size_t i = 0; i < segments; ++i) {
    const Vec2 to = at((i + 1) % n);
    if (to == segment_start(path, path.segs.size()) && p.vertices[i].bulge == 0.0) continue;
    path.segs.push_back(
        bulge_segment(segment_start(path, path.segs.size()), to, sign * p.vertices[i].bulge));
  }
  if (!path.segs.empty()) keep(std::move(path));
}

// The chordal tolerance of a spline: the user's, raised to kMinSplineTolerance
// and to kSplineRelativeTolerance of the control points' extent.
double spline_tolerance(const std::vector<WeightedPoint>& control, double tolerance) {
  Vec2 lo = control.front().p;
  Vec2 hi = lo;
  for (const WeightedPoint& c : control) {
    lo = {std::min(lo.x, c.p.x), std::min(lo.y, c.p.y)};
    hi = {std::max(hi.x, c.p.x), std::max(hi.y, c.p.y)};
  }
  return std::max({tolerance, kMinSplineTolerance,
                   kSplineRelativeTolerance * std::hypot(hi.x - lo.x, hi.y - lo.y)});
}

// Empty when the spline's control points are within what usina approximates,
// else why not. Work is (control points × degree)², as core's decomposition
// into Bézier pieces takes; the budget is the drawing's.
std::string Collector::spline_beyond_limits(const SplineData& s) {
  double w_min = 1.0;
  double w_max = 1.0;
  for (const WeightedPoint& c : s.control) {
    if (!within_range(c.p)) {
      return fmt::format("a control point is not a number or beyond ±{:g} mm",
                         kMaxDrawingCoordinate);
    }
    w_min = std::min(w_min, c.w);
    w_max = std::max(w_max, c.w);
  }
  if (w_min > 0.0 && std::isfinite(w_max) && w_max > kMaxSplineWeightRatio * w_min) {
    return fmt::format("weights from {:g} to {:g} (usina takes a ratio of up to {:g})", w_min,
                       w_max, kMaxSplineWeightRatio);
  }
  if (s.degree < 1 || s.degree > 25) return {};  // approximate_spline says why
  const double size = static_cast<double>(s.control.size()) * s.degree;
  if (spline_work_ + size * size > kMaxSplineWork) {
    return fmt::format(
        "of degree {} with {} control points is too large (control points × degree "
        "up to {:.0f} in one drawing)",
        s.degree, s.control.size(), std::sqrt(kMaxSplineWork - spline_work_));
  }
  spline_work_ += size * size;
  return {};
}

void Collector::finish_spline() {
  SplineData s = std::move(*spline_);
  spline_.reset();
  std::vector<Vec2> pts;
  if (!s.control.empty()) {
    if (const std::string e = spline_beyond_limits(s); !e.empty()) {
      return warn(fmt::format("SPLINE {}; left out", e));
    }
    std::string error;
    pts = approximate_spline(s.degree, s.control, s.knots,
                             spline_tolerance(s.control, options_.spline_tolerance), error);
    if (pts.empty()) return warn(fmt::format("SPLINE {}; left out", error));
  } else if (s.fit.size() >= 2) {
    warn("SPLINE with fit points only: cut through its fit points as straight segments");
    pts = s.fit;
  } else {
    return warn("SPLINE with neither control points nor fit points; left out");
  }
  if (spline_points_ + pts.size() > kMaxSplinePoints) {
    return warn(
        fmt::format("SPLINE of {} points, more than the {} the splines of a drawing may "
                    "make (raise --spline-tolerance); left out",
                    pts.size(), kMaxSplinePoints));
  }
  spline_points_ += pts.size();
  Path path{pts.front(), {}, s.closed};
  for (std::size_t i = 1; i < pts.size(); ++i)
    path.segs.push_back({pts[i], std::nullopt, 0});
  keep(std::move(path));
}

std::optional<std::vector<Path>> finish(Collector& c, const std::string& name,
                                        const DxfOptions& options, core::DiagnosticSink& diags) {
  c.flush();
  if (c.paths.empty()) {
    const std::string where =
        options.layer ? fmt::format("on layer \"{}\"", *options.layer) : std::string("at all");
    diags.report({core::Code::DxfNoEntities,
                  core::Severity::Error,
                  {},
                  fmt::format("{}: no LINE, ARC, CIRCLE, POLYLINE, LWPOLYLINE or SPLINE {}{}", name,
                              where, c.on_layer > 0 ? " (only entities usina cannot cut)" : "")});
    return std::nullopt;
  }
  return std::move(c.paths);
}

std::nullopt_t unreadable(core::DiagnosticSink& diags, const std::string& name,
                          const std::string& why) {
  diags.report(
      {core::Code::DxfUnreadable, core::Severity::Error, {}, fmt::format("{}: {}", name, why)});
  return std::nullopt;
}

std::string too_big() {
  return fmt::format("larger than {} MiB, the most usina reads (a part's drawing is far smaller)",
                     kMaxDxfBytes >> 20);
}

std::string reason(int error) {
  return std::error_code(error, std::generic_category()).message();
}

// Reads every byte of `fd` up to kMaxDxfBytes; a pipe or a device is read
// the same way, so /dev/stdin and process substitution work and /dev/zero ends.
std::optional<std::string> fd_bytes(int fd, const std::string& file, core::DiagnosticSink& diags) {
  std::string bytes;
  std::array<char, 1 << 16> buf{};
  for (;;) {
    const ssize_t n = ::read(fd, buf.data(), buf.size());
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      return unreadable(diags, file, fmt::format("cannot read the drawing: {}", reason(errno)));
    }
    if (n == 0) return bytes;
    if (bytes.size() + static_cast<std::size_t>(n) > kMaxDxfBytes) {
      return unreadable(diags, file, too_big());
    }
    bytes.append(buf.data(), static_cast<std::size_t>(n));
  }
}

std::optional<std::string> file_bytes(const std::string& file, core::DiagnosticSink& diags) {
  const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) {
    return unreadable(diags, file, fmt::format("cannot open the drawing: {}", reason(errno)));
  }

  struct stat st {};

  std::optional<std::string> bytes;
  if (::fstat(fd, &st) != 0) {
    unreadable(diags, file, fmt::format("cannot read the drawing: {}", reason(errno)));
  } else if (S_ISDIR(st.st_mode)) {
    unreadable(diags, file, "a folder, not a drawing");
  } else if (S_ISREG(st.st_mode) && static_cast<std::uintmax_t>(st.st_size) > kMaxDxfBytes) {
    unreadable(diags, file, too_big());
  } else {
    bytes = fd_bytes(fd, file, diags);
  }
  ::close(fd);
  return bytes;
}

}  // namespace

std::optional<std::vector<Path>> read_dxf_text(std::string_view text, const std::string& name,
                                               const DxfOptions& options,
                                               core::DiagnosticSink& diags) {
  std::optional<std::string> checked = canonical_dxf(text, name, diags);
  if (!checked) return std::nullopt;
  std::istringstream in(std::move(*checked));
  Collector c(options, name, diags);
  DL_Dxf dxf;
  dxf.in(in, &c);  // ends: every line of `in` is within dxflib's limit
  return finish(c, name, options, diags);
}

std::optional<std::vector<Path>> read_dxf(std::istream& in, const std::string& name,
                                          const DxfOptions& options, core::DiagnosticSink& diags) {
  std::string bytes;
  std::array<char, 1 << 16> buf{};
  while (in.read(buf.data(), buf.size()) || in.gcount() > 0) {
    if (bytes.size() + static_cast<std::size_t>(in.gcount()) > kMaxDxfBytes) {
      return unreadable(diags, name, too_big());
    }
    bytes.append(buf.data(), static_cast<std::size_t>(in.gcount()));
  }
  if (in.bad()) return unreadable(diags, name, "cannot read the drawing");
  return read_dxf_text(bytes, name, options, diags);
}

std::optional<std::vector<Path>> read_dxf(const std::string& file, const DxfOptions& options,
                                          core::DiagnosticSink& diags) {
  std::optional<std::string> bytes = file_bytes(file, diags);
  if (!bytes) return std::nullopt;
  return read_dxf_text(*bytes, file, options, diags);
}

}  // namespace usina::cam
