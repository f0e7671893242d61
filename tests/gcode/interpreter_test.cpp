// The RS274NGC interpreter, program text in, canon ops out: each test runs a
// small program and checks the ops, the parameters or the one diagnostic.
#include "gcode/interp/interpreter.hpp"

#include <stdlib.h>
#include <unistd.h>

#include <cmath>
#include <fstream>
#include <memory>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include "canon/toolpath.hpp"
#include "core/source.hpp"
#include "core/units.hpp"

namespace usina::gcode {
namespace {

using canon::Arc;
using canon::Feed;
using canon::Traverse;
using core::Code;
using core::Vec3;

constexpr double kTol = 1e-9;
constexpr double kInch = core::kMmPerInch;

// One run of the interpreter over a program, with everything it wrote.
struct Run {
  core::SourceManager sources;
  core::DiagnosticList diags;
  canon::Toolpath path;
  std::unique_ptr<Interpreter> interp;
  bool ok = false;

  const std::vector<canon::Op>& ops() const { return path.ops(); }

  template <typename T>
  std::vector<T> all() const {
    std::vector<T> out;
    for (const canon::Op& op : path.ops()) {
      if (const T* t = std::get_if<T>(&op.kind)) out.push_back(*t);
    }
    return out;
  }

  // Ops of kind T with the location of the block that made them.
  template <typename T>
  std::vector<const canon::Op*> ops_of() const {
    std::vector<const canon::Op*> out;
    for (const canon::Op& op : path.ops()) {
      if (std::holds_alternative<T>(op.kind)) out.push_back(&op);
    }
    return out;
  }

  // End points of every motion op, in order.
  std::vector<Vec3> ends() const {
    std::vector<Vec3> out;
    for (const canon::Op& op : path.ops()) {
      if (const auto* t = std::get_if<Traverse>(&op.kind)) out.push_back(t->to);
      if (const auto* f = std::get_if<Feed>(&op.kind)) out.push_back(f->to);
      if (const auto* a = std::get_if<Arc>(&op.kind)) out.push_back(a->to);
      if (const auto* p = std::get_if<canon::Probe>(&op.kind)) out.push_back(p->to);
      if (const auto* s = std::get_if<canon::Spline>(&op.kind)) out.push_back(s->to);
    }
    return out;
  }

  // The names of the ops, in order ("traverse feed end").
  std::string kinds() const {
    std::string out;
    for (const canon::Op& op : path.ops()) {
      if (!out.empty()) out += ' ';
      out += canon::op_name(op.kind);
    }
    return out;
  }

  std::vector<core::Diagnostic> of_severity(core::Severity s) const {
    std::vector<core::Diagnostic> out;
    for (const core::Diagnostic& d : diags.all()) {
      if (d.severity == s) out.push_back(d);
    }
    return out;
  }

  double param(int index) const { return interp->parameters().get(index); }
};

std::unique_ptr<Run> run(const std::string& text, InterpOptions opts = {},
                         const std::vector<std::pair<int, double>>& params = {}) {
  auto r = std::make_unique<Run>();
  const std::uint32_t id = r->sources.add(core::SourceFile::from_string("test.ngc", text));
  r->interp = std::make_unique<Interpreter>(r->sources, std::move(opts), r->path, r->diags);
  for (const auto& [index, value] : params)
    r->interp->set_parameter(index, value);
  r->ok = r->interp->run(id);
  return r;
}

std::string show(const Vec3& v) {
  return fmt::format("({}, {}, {})", v.x, v.y, v.z);
}

#define EXPECT_VEC(actual, ...)                                                     \
  do {                                                                              \
    const Vec3 a_ = (actual);                                                       \
    const Vec3 e_{__VA_ARGS__};                                                     \
    EXPECT_TRUE(std::fabs(a_.x - e_.x) <= kTol && std::fabs(a_.y - e_.y) <= kTol && \
                std::fabs(a_.z - e_.z) <= kTol)                                     \
        << "actual " << show(a_) << ", expected " << show(e_);                      \
  } while (0)

// Runs `text`, which must succeed.
#define RUN_OK(r, ...)                                                           \
  auto r = run(__VA_ARGS__);                                                     \
  ASSERT_TRUE(r->ok) << (r->diags.all().empty() ? std::string("(no diagnostic)") \
                                                : r->diags.all()[0].message);    \
  ASSERT_EQ(r->diags.error_count(), 0)

// The run's first error must be `code` at `line`:`col`.
void expect_error(const Run& r, Code code, std::uint32_t line, std::uint32_t col) {
  EXPECT_FALSE(r.ok);
  const auto errors = r.of_severity(core::Severity::Error);
  ASSERT_EQ(errors.size(), 1u) << "expected exactly one error";
  const core::Diagnostic& d = errors[0];
  EXPECT_EQ(core::code_name(d.code), core::code_name(code)) << d.message;
  EXPECT_EQ(d.loc.line, line) << d.message;
  EXPECT_EQ(d.loc.col, col) << d.message;
  EXPECT_FALSE(d.message.empty());
}

// A program that must stop at one error: `code` at `line`:`col`.
struct ErrorCase {
  const char* what;  // the rule the row checks
  const char* program;
  Code code;
  std::uint32_t line;
  std::uint32_t col;
  bool with_tools = false;  // run with tools() in the table
};

InterpOptions with_tools();

template <std::size_t N>
void expect_errors(const ErrorCase (&cases)[N]) {
  for (const ErrorCase& c : cases) {
    SCOPED_TRACE(std::string(c.what) + ": " + c.program);
    auto r = run(c.program, c.with_tools ? with_tools() : InterpOptions{});
    expect_error(*r, c.code, c.line, c.col);
  }
}

ToolTable tools() {
  ToolTable t;
  ToolEntry one;
  one.number = 1;
  one.offset = {0, 0, 10};
  one.diameter = 6;
  t.set(one);
  ToolEntry two;
  two.number = 2;
  two.offset = {0, 0, 25};
  two.diameter = 12.7;
  t.set(two);
  return t;
}

InterpOptions with_tools() {
  InterpOptions o;
  o.tools = tools();
  return o;
}

// A temporary folder for subroutine files, removed afterwards.
class TempDir {
 public:
  TempDir() {
    char tmpl[] = "/tmp/usina_interp_test_XXXXXX";
    const char* d = mkdtemp(tmpl);
    EXPECT_NE(d, nullptr);
    path_ = d != nullptr ? d : "/tmp";
  }

  ~TempDir() {
    for (const std::string& f : files_)
      ::unlink(f.c_str());
    ::rmdir(path_.c_str());
  }

  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  std::string write(const std::string& name, const std::string& text) {
    const std::string p = path_ + "/" + name;
    std::ofstream(p, std::ios::binary) << text;
    files_.push_back(p);
    return p;
  }

  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::vector<std::string> files_;
};

// ============================================================================
// Straight moves, units, distance modes
// ============================================================================

TEST(InterpMotion, RapidMoveIsATraverseInAbsoluteMm) {
  RUN_OK(r, "G21 G90\nG0 X1 Y2 Z3\nM2\n");
  EXPECT_EQ(r->kinds(), "traverse end");
  const auto t = r->all<Traverse>();
  ASSERT_EQ(t.size(), 1u);
  EXPECT_VEC(t[0].to, 1, 2, 3);
}

TEST(InterpMotion, OpsCarryTheLineAndColumnOfTheirBlock) {
  RUN_OK(r, "G0 X1\n\n   G0 X2\nM2\n");
  const auto t = r->ops_of<Traverse>();
  ASSERT_EQ(t.size(), 2u);
  EXPECT_EQ(t[0]->src.line, 1u);
  EXPECT_EQ(t[0]->src.col, 1u);
  EXPECT_EQ(t[1]->src.line, 3u);
  EXPECT_EQ(t[1]->src.col, 4u);
  EXPECT_EQ(r->ops().back().src.line, 4u);
}

TEST(InterpMotion, FeedMoveCarriesTheFeedRate) {
  RUN_OK(r, "G1 X5 F120\nM2\n");
  const auto f = r->all<Feed>();
  ASSERT_EQ(f.size(), 1u);
  EXPECT_VEC(f[0].to, 5, 0, 0);
  ASSERT_TRUE(f[0].f.has_value());
  EXPECT_DOUBLE_EQ(*f[0].f, 120.0);
}

TEST(InterpMotion, InchWordsAndFeedBecomeMm) {
  RUN_OK(r, "G20\nG0 X1 Y-2\nG1 Z0.5 F10\nM2\n");
  const auto t = r->all<Traverse>();
  const auto f = r->all<Feed>();
  ASSERT_EQ(t.size(), 1u);
  ASSERT_EQ(f.size(), 1u);
  EXPECT_VEC(t[0].to, kInch, -2 * kInch, 0);
  EXPECT_VEC(f[0].to, kInch, -2 * kInch, 0.5 * kInch);
  EXPECT_NEAR(*f[0].f, 10 * kInch, kTol);
}

TEST(InterpMotion, G21AfterG20MakesWordsMmAgain) {
  RUN_OK(r, "G20\nG0 X1\nG21\nG0 X1\nM2\n");
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 2u);
  EXPECT_VEC(e[0], kInch, 0, 0);
  EXPECT_VEC(e[1], 1, 0, 0);
}

TEST(InterpMotion, FeedSetInInchKeepsItsSpeedAfterG21) {
  RUN_OK(r, "G20\nF10\nG21\nG1 X1\nM2\n");
  const auto f = r->all<Feed>();
  ASSERT_EQ(f.size(), 1u);
  EXPECT_NEAR(*f[0].f, 254.0, kTol);
}

TEST(InterpMotion, IncrementalG91AddsToTheCurrentPoint) {
  RUN_OK(r, "G91\nG0 X1\nG0 X1 Y2\nG90\nG0 X0\nM2\n");
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 3u);
  EXPECT_VEC(e[0], 1, 0, 0);
  EXPECT_VEC(e[1], 2, 2, 0);
  EXPECT_VEC(e[2], 0, 2, 0);
}

TEST(InterpMotion, IncrementalInchSteps) {
  RUN_OK(r, "G20 G91\nG0 X1\nG0 X1\nM2\n");
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 2u);
  EXPECT_VEC(e[1], 2 * kInch, 0, 0);
}

TEST(InterpMotion, MotionModeStaysForLaterBlocks) {
  RUN_OK(r, "G1 X2 F100\nX1\nY1\nM2\n");
  EXPECT_EQ(r->kinds(), "feed feed feed end");
}

TEST(InterpMotion, FeedInTheBlockOfG20IsReadBeforeTheUnitsChange) {
  // RS274NGC order of execution: F (step 3) before units (step 12), so F10
  // here is 10 mm/min, and stays that speed in inch.
  RUN_OK(r, "G20 F10\nG1 X1\n#1=#<_feed>\nM2\n");
  EXPECT_NEAR(*r->all<Feed>()[0].f, 10.0, kTol);
  EXPECT_NEAR(r->param(1), 10.0 / kInch, kTol);
}

TEST(InterpMotion, G80BesideAMotionCodeIsAccepted) {
  RUN_OK(r, "G0 G80 X1\nG80 G1 X2 F10\nM2\n");
  EXPECT_EQ(r->kinds(), "traverse feed end");
}

TEST(InterpMotion, UnchangedAxesKeepTheirValue) {
  RUN_OK(r, "G0 X1 Y2 Z3\nG0 Y5\nM2\n");
  EXPECT_VEC(r->ends()[1], 1, 5, 3);
}

TEST(InterpMotion, RotaryAxesGoToAbcInDegreesNotScaledByInch) {
  RUN_OK(r, "G20\nG0 X1 A90\nM2\n");
  const auto t = r->all<Traverse>();
  ASSERT_EQ(t.size(), 1u);
  EXPECT_VEC(t[0].to, kInch, 0, 0);
  EXPECT_DOUBLE_EQ(t[0].abc[0], 90.0);
}

TEST(InterpMotion, CrLfProgramRunsLikeLf) {
  RUN_OK(r, "G0 X1\r\nG0 X2\r\nM2\r\n");
  EXPECT_EQ(r->kinds(), "traverse traverse end");
}

// ============================================================================
// Arcs
// ============================================================================

TEST(InterpArc, G2WithIjIsClockwiseAboutTheOffsetCentre) {
  RUN_OK(r, "G1 F100\nG2 X10 Y0 I5 J0\nM2\n");
  const auto a = r->all<Arc>();
  ASSERT_EQ(a.size(), 1u);
  EXPECT_VEC(a[0].to, 10, 0, 0);
  EXPECT_VEC(a[0].center, 5, 0, 0);
  EXPECT_VEC(a[0].normal, 0, 0, 1);
  EXPECT_EQ(a[0].turn, -1);
  EXPECT_DOUBLE_EQ(*a[0].f, 100.0);
}

TEST(InterpArc, G3IsCounterClockwiseAndAMissingJIsZero) {
  RUN_OK(r, "G1 F100\nG3 X10 Y0 I5\nM2\n");
  const auto a = r->all<Arc>();
  ASSERT_EQ(a.size(), 1u);
  EXPECT_VEC(a[0].center, 5, 0, 0);
  EXPECT_EQ(a[0].turn, 1);
}

TEST(InterpArc, CentreOffsetIsFromTheStartPoint) {
  RUN_OK(r, "G0 X10 Y10\nG1 F100\nG3 X0 Y10 I-5 J0\nM2\n");
  EXPECT_VEC(r->all<Arc>()[0].center, 5, 10, 0);
}

TEST(InterpArc, RFormatPositiveRadiusTakesTheShortArc) {
  // Chord (0,0)-(10,10), R10: the centres are (0,10) and (10,0); G3 short
  // is the one left of the chord.
  RUN_OK(r, "G1 F100\nG3 X10 Y10 R10\nM2\n");
  const auto a = r->all<Arc>();
  ASSERT_EQ(a.size(), 1u);
  EXPECT_VEC(a[0].center, 0, 10, 0);
  EXPECT_EQ(a[0].turn, 1);
}

TEST(InterpArc, RFormatNegativeRadiusTakesTheLongArc) {
  RUN_OK(r, "G1 F100\nG3 X10 Y10 R-10\nM2\n");
  EXPECT_VEC(r->all<Arc>()[0].center, 10, 0, 0);
}

TEST(InterpArc, RFormatClockwiseShortArc) {
  RUN_OK(r, "G1 F100\nG2 X10 Y10 R10\nM2\n");
  const auto a = r->all<Arc>();
  EXPECT_VEC(a[0].center, 10, 0, 0);
  EXPECT_EQ(a[0].turn, -1);
}

TEST(InterpArc, RFormatInInchIsScaled) {
  RUN_OK(r, "G20 G1 F10\nG3 X1 Y1 R1\nM2\n");
  EXPECT_VEC(r->all<Arc>()[0].center, 0, kInch, 0);
}

TEST(InterpArc, RFormatHalfCircleWithinToleranceUsesTheMidpoint) {
  // Half the chord is 5; R 4.9995 is within the 0.001 mm a program may be off.
  RUN_OK(r, "G1 F100\nG2 X10 R4.9995\nM2\n");
  EXPECT_VEC(r->all<Arc>()[0].center, 5, 0, 0);
}

TEST(InterpArc, FullCircleWhenTheEndIsTheStart) {
  RUN_OK(r, "G1 F100\nG2 X0 Y0 I5\nM2\n");
  const auto a = r->all<Arc>();
  ASSERT_EQ(a.size(), 1u);
  EXPECT_VEC(a[0].to, 0, 0, 0);
  EXPECT_VEC(a[0].center, 5, 0, 0);
  EXPECT_EQ(a[0].turn, -1);
}

TEST(InterpArc, PCountsTurns) {
  RUN_OK(r, "G1 F100\nG3 X0 Y0 I5 P3\nG2 X0 Y0 I5 P2\nM2\n");
  const auto a = r->all<Arc>();
  ASSERT_EQ(a.size(), 2u);
  EXPECT_EQ(a[0].turn, 3);
  EXPECT_EQ(a[1].turn, -2);
}

TEST(InterpArc, HelixEndsAtTheAxialWordAndCentreHasTheStartsAxialCoordinate) {
  RUN_OK(r, "G1 Z2 F100\nG3 X0 Y0 Z-5 I5 P2\nM2\n");
  const auto a = r->all<Arc>();
  ASSERT_EQ(a.size(), 1u);
  EXPECT_VEC(a[0].to, 0, 0, -5);
  EXPECT_VEC(a[0].center, 5, 0, 2);
  EXPECT_EQ(a[0].turn, 2);
}

TEST(InterpArc, G18UsesZAndXWithNormalY) {
  RUN_OK(r, "G1 F100\nG18 G2 X10 Z0 I5 K0\nM2\n");
  const auto a = r->all<Arc>();
  ASSERT_EQ(a.size(), 1u);
  EXPECT_VEC(a[0].to, 10, 0, 0);
  EXPECT_VEC(a[0].center, 5, 0, 0);
  EXPECT_VEC(a[0].normal, 0, 1, 0);
  EXPECT_EQ(a[0].turn, -1);
}

TEST(InterpArc, G18RFormatShortArcIsCounterClockwiseSeenFromPlusY) {
  // In (Z, X) coordinates the chord runs (0,0)-(10,10); the G3 short-arc
  // centre is (Z0, X10).
  RUN_OK(r, "G1 F100\nG18 G3 X10 Z10 R10\nM2\n");
  const auto a = r->all<Arc>();
  ASSERT_EQ(a.size(), 1u);
  EXPECT_VEC(a[0].center, 10, 0, 0);
  EXPECT_EQ(a[0].turn, 1);
}

TEST(InterpArc, G18HelixMovesAlongY) {
  RUN_OK(r, "G1 F100\nG18 G3 X10 Z0 Y3 I5\nM2\n");
  const auto a = r->all<Arc>();
  EXPECT_VEC(a[0].to, 10, 3, 0);
  EXPECT_VEC(a[0].center, 5, 0, 0);
}

TEST(InterpArc, G19UsesYAndZWithNormalX) {
  RUN_OK(r, "G1 F100\nG19 G2 Y10 Z0 J5\nG19 G3 Y20 Z10 R10\nM2\n");
  const auto a = r->all<Arc>();
  ASSERT_EQ(a.size(), 2u);
  EXPECT_VEC(a[0].center, 0, 5, 0);
  EXPECT_VEC(a[0].normal, 1, 0, 0);
  EXPECT_EQ(a[0].turn, -1);
  // From (Y10, Z0) to (Y20, Z10), G3 short: centre (Y10, Z10).
  EXPECT_VEC(a[1].center, 0, 10, 10);
}

TEST(InterpArc, G901MakesIjAbsoluteAndG911Incremental) {
  RUN_OK(r, "G1 F100\nG0 X2\nG90.1\nG3 X8 Y0 I5 J0\nG91.1\nG0 X2\nG3 X8 I3\nM2\n");
  const auto a = r->all<Arc>();
  ASSERT_EQ(a.size(), 2u);
  EXPECT_VEC(a[0].center, 5, 0, 0);
  EXPECT_VEC(a[1].center, 5, 0, 0);
}

TEST(InterpArc, ArcInIncrementalModeEndsRelativeToTheStart) {
  RUN_OK(r, "G0 X10\nG91 G1 F100\nG3 X-10 Y10 I-10\nM2\n");
  const auto a = r->all<Arc>();
  EXPECT_VEC(a[0].to, 0, 10, 0);
  EXPECT_VEC(a[0].center, 0, 0, 0);
}

TEST(InterpArc, InchCentreOffsetsAreScaled) {
  RUN_OK(r, "G20 G1 F10\nG2 X2 I1\nM2\n");
  EXPECT_VEC(r->all<Arc>()[0].center, kInch, 0, 0);
}

// ============================================================================
// Polar coordinates
// ============================================================================

TEST(InterpPolar, RadiusAndAngleAboutTheOrigin) {
  RUN_OK(r, "G0 @10 ^90\nG1 @10 ^0 F100\nM2\n");
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 2u);
  EXPECT_VEC(e[0], 0, 10, 0);
  EXPECT_VEC(e[1], 10, 0, 0);
}

TEST(InterpPolar, IncrementalAddsToThePolarCoordinatesOfTheCurrentPoint) {
  RUN_OK(r, "G0 @10 ^0\nG91 G0 ^90\nG0 @5\nM2\n");
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 3u);
  EXPECT_VEC(e[1], 0, 10, 0);
  EXPECT_VEC(e[2], 0, 15, 0);
}

TEST(InterpPolar, RadiusInInch) {
  RUN_OK(r, "G20 G0 @1 ^180\nM2\n");
  EXPECT_VEC(r->ends()[0], -kInch, 0, 0);
}

TEST(InterpPolar, PolarWithXIsAnError) {
  auto r = run("G0 @10 X5\nM2\n");
  expect_error(*r, Code::AxisWordsConflict, 1, 8);
}

TEST(InterpPolar, PolarOutsideG17IsAnError) {
  auto r = run("G18\nG0 @10 ^0\nM2\n");
  expect_error(*r, Code::NotAllowedInMode, 2, 1);
}

// ============================================================================
// G92, G52, work offsets, G53, G28/G30
// ============================================================================

TEST(InterpOffsets, G92MakesTheCurrentPointReadTheGivenValue) {
  RUN_OK(r, "G0 X10\nG92 X0\nG0 X5\nM2\n");
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 2u) << "G92 itself does not move";
  EXPECT_VEC(e[1], 15, 0, 0);
  EXPECT_DOUBLE_EQ(r->param(5211), 10.0);
  EXPECT_DOUBLE_EQ(r->param(5210), 1.0);
}

TEST(InterpOffsets, G92InInchStoresMachineUnits) {
  RUN_OK(r, "G20\nG0 X1\nG92 X0\nG0 X1\nM2\n");
  EXPECT_VEC(r->ends()[1], 2 * kInch, 0, 0);
  EXPECT_NEAR(r->param(5211), kInch, kTol);
}

TEST(InterpOffsets, G921ClearsTheOffsetAndItsParameters) {
  RUN_OK(r, "G0 X10\nG92 X0\nG92.1\nG0 X5\nM2\n");
  EXPECT_VEC(r->ends().back(), 5, 0, 0);
  EXPECT_DOUBLE_EQ(r->param(5211), 0.0);
  EXPECT_DOUBLE_EQ(r->param(5210), 0.0);
}

TEST(InterpOffsets, G922ClearsTheOffsetButKeepsItsParametersForG923) {
  RUN_OK(r, "G0 X10\nG92 X0\nG92.2\nG0 X5\nG92.3\nG0 X5\nM2\n");
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 3u);
  EXPECT_VEC(e[1], 5, 0, 0);
  EXPECT_VEC(e[2], 15, 0, 0);
  EXPECT_DOUBLE_EQ(r->param(5211), 10.0);
}

TEST(InterpOffsets, G52ShiftsTheOriginByTheGivenValue) {
  RUN_OK(r, "G0 X1\nG52 X5 Y-1\nG0 X0 Y0\nG52 X0 Y0\nG0 X0 Y0\nM2\n");
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 3u);
  EXPECT_VEC(e[1], 5, -1, 0);
  EXPECT_VEC(e[2], 0, 0, 0);
}

TEST(InterpOffsets, G10L2SetsTheActiveWorkOffset) {
  RUN_OK(r, "G10 L2 P1 X10 Y5\nG0 X0 Y0\nM2\n");
  EXPECT_VEC(r->ends()[0], 10, 5, 0);
  EXPECT_DOUBLE_EQ(r->param(5221), 10.0);
  EXPECT_DOUBLE_EQ(r->param(5222), 5.0);
}

TEST(InterpOffsets, G10L2OnAnotherSystemTakesEffectWhenSelected) {
  RUN_OK(r, "G10 L2 P2 X20\nG0 X0\nG55\nG0 X0\n#1=#<_coord_system>\nM2\n");
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 2u);
  EXPECT_VEC(e[0], 0, 0, 0);
  EXPECT_VEC(e[1], 20, 0, 0);
  EXPECT_DOUBLE_EQ(r->param(5241), 20.0);
  EXPECT_DOUBLE_EQ(r->param(5220), 2.0);
  EXPECT_DOUBLE_EQ(r->param(1), 550.0);
}

TEST(InterpOffsets, G10L2P0MeansTheActiveSystem) {
  RUN_OK(r, "G56\nG10 L2 P0 X3\nG0 X0\nM2\n");
  EXPECT_VEC(r->ends()[0], 3, 0, 0);
  EXPECT_DOUBLE_EQ(r->param(5261), 3.0);
}

TEST(InterpOffsets, G593IsTheNinthSystem) {
  RUN_OK(r, "G10 L2 P9 X7\nG59.3\nG0 X0\n#1=#<_coord_system>\nM2\n");
  EXPECT_VEC(r->ends()[0], 7, 0, 0);
  EXPECT_DOUBLE_EQ(r->param(5381), 7.0);
  EXPECT_DOUBLE_EQ(r->param(1), 593.0);
}

TEST(InterpOffsets, G10L2InInchStoresMachineUnits) {
  RUN_OK(r, "G20\nG10 L2 P1 X1\nG0 X0\nM2\n");
  EXPECT_VEC(r->ends()[0], kInch, 0, 0);
  EXPECT_NEAR(r->param(5221), kInch, kTol);
}

TEST(InterpOffsets, G10L2RRotatesTheSystemAboutItsOrigin) {
  RUN_OK(r, "G10 L2 P1 X100 R90\nG0 X10 Y0\nM2\n");
  EXPECT_VEC(r->ends()[0], 100, 10, 0);
  EXPECT_DOUBLE_EQ(r->param(5230), 90.0);
}

TEST(InterpOffsets, RotatedArcHasARotatedCentre) {
  RUN_OK(r, "G10 L2 P1 R90\nG1 F100\nG2 X10 I5\nM2\n");
  const auto a = r->all<Arc>();
  ASSERT_EQ(a.size(), 1u);
  EXPECT_VEC(a[0].to, 0, 10, 0);
  EXPECT_VEC(a[0].center, 0, 5, 0);
  EXPECT_VEC(a[0].normal, 0, 0, 1);
  EXPECT_EQ(a[0].turn, -1);
}

TEST(InterpOffsets, G10L20MakesTheCurrentPointReadTheGivenValue) {
  RUN_OK(r, "G0 X3\nG10 L20 P1 X5\nG0 X5\nG0 X10\nM2\n");
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 3u);
  EXPECT_VEC(e[1], 3, 0, 0);
  EXPECT_VEC(e[2], 8, 0, 0);
  EXPECT_DOUBLE_EQ(r->param(5221), -2.0);
}

TEST(InterpOffsets, G53MovesInMachineCoordinatesForOneBlock) {
  RUN_OK(r, "G10 L2 P1 X10\nG0 X0\nG53 G0 X0\nG0 X1\nM2\n");
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 3u);
  EXPECT_VEC(e[0], 10, 0, 0);
  EXPECT_VEC(e[1], 0, 0, 0);
  EXPECT_VEC(e[2], 11, 0, 0);
}

TEST(InterpOffsets, G53IsAbsoluteEvenUnderG91) {
  RUN_OK(r, "G91\nG0 X5\nG53 G0 X1\nM2\n");
  EXPECT_VEC(r->ends()[1], 1, 0, 0);
}

TEST(InterpOffsets, G53WithG1Feeds) {
  RUN_OK(r, "G10 L2 P1 X10\nG53 G1 X2 F100\nM2\n");
  EXPECT_EQ(r->kinds(), "feed end");
  EXPECT_VEC(r->ends()[0], 2, 0, 0);
}

TEST(InterpOffsets, G53WithAnArcIsAnError) {
  auto r = run("G1 F100\nG53 G2 X1 I1\nM2\n");
  expect_error(*r, Code::NotAllowedInMode, 2, 1);
}

TEST(InterpOffsets, G28GoesToThePositionStoredByG281) {
  // LinuxCNC moves to the intermediate point even without axis words (a
  // move to where the tool is), then home.
  RUN_OK(r, "G0 X3 Y4 Z5\nG28.1\nG0 X0 Y0 Z0\nG28\nM2\n");
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 4u);
  EXPECT_VEC(e[2], 0, 0, 0);
  EXPECT_VEC(e[3], 3, 4, 5);
  EXPECT_DOUBLE_EQ(r->param(5161), 3.0);
  EXPECT_DOUBLE_EQ(r->param(5162), 4.0);
  EXPECT_DOUBLE_EQ(r->param(5163), 5.0);
}

TEST(InterpOffsets, G28WithAnAxisWordGoesThroughItAndHomesOnlyThatAxis) {
  RUN_OK(r, "G0 X3 Y4 Z5\nG28.1\nG0 X1 Y1 Z0\nG28 Z2\nM2\n");
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 4u);
  EXPECT_VEC(e[2], 1, 1, 2);
  EXPECT_VEC(e[3], 1, 1, 5);
}

TEST(InterpOffsets, G28HomeIsInMachineCoordinates) {
  RUN_OK(r, "G10 L2 P1 X10\nG0 X3\nG28.1\nG0 X0\nG28\nM2\n");
  EXPECT_DOUBLE_EQ(r->param(5161), 13.0);
  EXPECT_VEC(r->ends().back(), 13, 0, 0);
}

TEST(InterpOffsets, G28UsesAPresetParameter) {
  RUN_OK(r, "G28\nM2\n", {}, {{5161, 50}, {5163, 20}});
  EXPECT_VEC(r->ends().back(), 50, 0, 20);
}

TEST(InterpOffsets, G30GoesToThePositionStoredByG301) {
  RUN_OK(r, "G0 X1 Y2 Z3\nG30.1\nG0 X0 Y0 Z0\nG30\nM2\n");
  EXPECT_VEC(r->ends().back(), 1, 2, 3);
  EXPECT_DOUBLE_EQ(r->param(5181), 1.0);
  EXPECT_DOUBLE_EQ(r->param(5183), 3.0);
}

// Regression (a bug the tests found, fixed): the work offset and G92 offset held by the parameters
// at the start
// (#5220 and #5221.., #5210 and #5211.., as a var file gives them) are not
// applied until the program selects a system or runs G92.3. LinuxCNC restores
// both when the interpreter starts (rs274ngc_pre.cc, Interp::init: origin
// offsets from pars[5220]'s system, axis offsets when pars[5210] is set).
// Expected: with #5221 = 10, `G0 X0` goes to absolute X10; with #5210 = 1 and
// #5211 = 3 to X3. Actual: X0 both times (g5x and g92 start at zero).
TEST(InterpOffsets, OffsetsFromParametersApplyAtStart) {
  RUN_OK(r, "G0 X0\nM2\n", {}, {{5220, 1}, {5221, 10}});
  EXPECT_VEC(r->ends()[0], 10, 0, 0);
  RUN_OK(g92, "G0 X0\nM2\n", {}, {{5210, 1}, {5211, 3}});
  EXPECT_VEC(g92->ends()[0], 3, 0, 0);
}

TEST(InterpOffsets, WorkOffsetFromParametersAppliesWhenSelected) {
  RUN_OK(r, "G54\nG0 X0\nM2\n", {}, {{5221, 10}});
  EXPECT_VEC(r->ends()[0], 10, 0, 0);
}

// ============================================================================
// Tool length offsets, tools, spindle, coolant, dwell
// ============================================================================

TEST(InterpTools, G43HShiftsProgramZByTheToolLength) {
  RUN_OK(r, "G43 H1\n#1=#<_z>\n#2=#<_tool_offset>\nG53 G0 Z0\nG49\n#3=#<_z>\nG53 G0 Z0\nM2\n",
         with_tools());
  EXPECT_DOUBLE_EQ(r->param(1), -10.0);
  EXPECT_DOUBLE_EQ(r->param(2), 1.0);
  EXPECT_DOUBLE_EQ(r->param(3), 0.0);
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 2u);
  // G53 Z0 puts the spindle at machine zero: the tip is a tool length below.
  EXPECT_VEC(e[0], 0, 0, -10);
  EXPECT_VEC(e[1], 0, 0, 0);
}

TEST(InterpTools, G43WithoutHUsesTheToolInTheSpindle) {
  RUN_OK(r, "T2 M6\nG43\n#1=#<_z>\nM2\n", with_tools());
  EXPECT_DOUBLE_EQ(r->param(1), -25.0);
}

TEST(InterpTools, G43InInchReadsZInInch) {
  RUN_OK(r, "G20\nG43 H1\n#1=#<_z>\nM2\n", with_tools());
  EXPECT_NEAR(r->param(1), -10.0 / kInch, kTol);
}

TEST(InterpTools, ToolTableInInchMachineUnits) {
  InterpOptions o = with_tools();
  o.machine_units = core::LengthUnit::Inch;
  ToolEntry t;
  t.number = 5;
  t.offset = {0, 0, kInch};  // tables are read into mm
  o.tools.set(t);
  RUN_OK(r, "G43 H5\nG53 G0 Z0\nM2\n", std::move(o));
  EXPECT_VEC(r->ends()[0], 0, 0, -kInch);
}

TEST(InterpTools, G10L1AddsAToolThatG43AndM6Use) {
  RUN_OK(r, "G10 L1 P3 Z7 R2\nT3 M6\nG43 H3\n#1=#<_z>\nM2\n");
  const auto t = r->all<canon::ToolChange>();
  ASSERT_EQ(t.size(), 1u);
  EXPECT_EQ(t[0].tool, 3);
  ASSERT_TRUE(t[0].diameter.has_value());
  EXPECT_DOUBLE_EQ(*t[0].diameter, 4.0);
  EXPECT_DOUBLE_EQ(r->param(1), -7.0);
}

TEST(InterpTools, G10L10SetsTheLengthThatMakesTheCurrentPointReadTheValue) {
  RUN_OK(r, "G0 Z5\nG10 L10 P3 Z0\nG43 H3\n#1=#<_z>\nM2\n");
  EXPECT_NEAR(r->param(1), 0.0, kTol);
}

TEST(InterpTools, M6EmitsTheToolWithItsDiameter) {
  RUN_OK(r, "T2 M6\n#1=#<_current_tool>\n#2=#5400\nM2\n", with_tools());
  const auto t = r->all<canon::ToolChange>();
  ASSERT_EQ(t.size(), 1u);
  EXPECT_EQ(t[0].tool, 2);
  EXPECT_DOUBLE_EQ(*t[0].diameter, 12.7);
  EXPECT_DOUBLE_EQ(r->param(1), 2.0);
  EXPECT_DOUBLE_EQ(r->param(2), 2.0);
}

TEST(InterpTools, ToolNotInTheTableHasNoDiameter) {
  RUN_OK(r, "T9 M6\nM2\n");
  const auto t = r->all<canon::ToolChange>();
  ASSERT_EQ(t.size(), 1u);
  EXPECT_EQ(t[0].tool, 9);
  EXPECT_FALSE(t[0].diameter.has_value());
}

TEST(InterpTools, TSelectsWithoutChanging) {
  RUN_OK(r, "T4\n#1=#<_selected_tool>\n#2=#<_current_tool>\nM2\n");
  EXPECT_TRUE(r->all<canon::ToolChange>().empty());
  EXPECT_DOUBLE_EQ(r->param(1), 4.0);
  EXPECT_DOUBLE_EQ(r->param(2), 0.0);
}

TEST(InterpTools, M6StopsARunningSpindleFirst) {
  RUN_OK(r, "S1000 M3\nT1 M6\nM2\n", with_tools());
  EXPECT_EQ(r->kinds(), "spindle spindle tool end");
  const auto s = r->all<canon::Spindle>();
  EXPECT_EQ(s[1].dir, canon::SpindleDir::Off);
}

TEST(InterpTools, M61SetsTheToolNumberFromQ) {
  RUN_OK(r, "M61 Q4\n#1=#<_current_tool>\nM2\n");
  EXPECT_DOUBLE_EQ(r->param(1), 4.0);
}

TEST(InterpSpindle, M3M4M5WithTheSpeed) {
  RUN_OK(r, "S1000 M3\n#1=#<_spindle_on>\nM4\nM5\n#2=#<_spindle_on>\nM2\n");
  const auto s = r->all<canon::Spindle>();
  ASSERT_EQ(s.size(), 3u);
  EXPECT_EQ(s[0].dir, canon::SpindleDir::Cw);
  EXPECT_DOUBLE_EQ(s[0].rpm, 1000.0);
  EXPECT_EQ(s[1].dir, canon::SpindleDir::Ccw);
  EXPECT_EQ(s[2].dir, canon::SpindleDir::Off);
  EXPECT_DOUBLE_EQ(r->param(1), 1.0);
  EXPECT_DOUBLE_EQ(r->param(2), 0.0);
}

TEST(InterpSpindle, SpeedWordInTheSameBlockAppliesToM3) {
  RUN_OK(r, "M3 S2400\nM2\n");
  EXPECT_DOUBLE_EQ(r->all<canon::Spindle>()[0].rpm, 2400.0);
}

TEST(InterpSpindle, ProgramEndStopsTheSpindle) {
  RUN_OK(r, "S500 M3\nM2\n");
  EXPECT_EQ(r->kinds(), "spindle spindle end");
  EXPECT_EQ(r->all<canon::Spindle>()[1].dir, canon::SpindleDir::Off);
}

TEST(InterpCoolant, M7MistM8FloodM9Off) {
  RUN_OK(r, "M7\nM8\nM9\nM2\n");
  const auto c = r->all<canon::Coolant>();
  ASSERT_EQ(c.size(), 3u);
  EXPECT_TRUE(c[0].mist);
  EXPECT_FALSE(c[0].flood);
  EXPECT_TRUE(c[1].mist);
  EXPECT_TRUE(c[1].flood);
  EXPECT_FALSE(c[2].mist);
  EXPECT_FALSE(c[2].flood);
}

TEST(InterpCoolant, M7AndM8InOneBlockTurnBothOn) {
  RUN_OK(r, "M8 M7\n#1=#<_mist>\n#2=#<_flood>\nM2\n");
  const auto c = r->all<canon::Coolant>();
  ASSERT_EQ(c.size(), 1u);
  EXPECT_TRUE(c[0].mist);
  EXPECT_TRUE(c[0].flood);
  EXPECT_DOUBLE_EQ(r->param(1), 1.0);
  EXPECT_DOUBLE_EQ(r->param(2), 1.0);
}

TEST(InterpDwell, G4PIsSeconds) {
  RUN_OK(r, "G4 P1.5\nM2\n");
  const auto d = r->all<canon::Dwell>();
  ASSERT_EQ(d.size(), 1u);
  EXPECT_DOUBLE_EQ(d[0].s, 1.5);
}

TEST(InterpDwell, DwellComesBeforeTheMotionOfItsBlock) {
  RUN_OK(r, "G4 P2 G0 X1\nM2\n");
  EXPECT_EQ(r->kinds(), "dwell traverse end");
}

// ============================================================================
// Feed modes
// ============================================================================

TEST(InterpFeedMode, InverseTimeFeedHasNoMmPerMinuteRate) {
  RUN_OK(r, "G93 G1 X1 F2\nG2 X3 I1 F4\nM2\n");
  const auto f = r->all<Feed>();
  ASSERT_EQ(f.size(), 1u);
  EXPECT_FALSE(f[0].f.has_value());
  EXPECT_FALSE(r->all<Arc>()[0].f.has_value());
}

TEST(InterpFeedMode, PerRevolutionFeedHasNoMmPerMinuteRate) {
  RUN_OK(r, "G95 G1 X1 F0.1\nG94 G1 X2 F100\nM2\n");
  const auto f = r->all<Feed>();
  ASSERT_EQ(f.size(), 2u);
  EXPECT_FALSE(f[0].f.has_value());
  ASSERT_TRUE(f[1].f.has_value());
  EXPECT_DOUBLE_EQ(*f[1].f, 100.0);
}

TEST(InterpFeedMode, InverseTimeNeedsFOnEveryMove) {
  auto r = run("G93 G1 X1 F2\nG1 X2\nM2\n");
  expect_error(*r, Code::NoFeedRate, 2, 1);
}

TEST(InterpFeedMode, EnteringInverseTimeForgetsTheFeed) {
  auto r = run("G1 X1 F100\nG93\nG94\nG1 X2\nM2\n");
  expect_error(*r, Code::NoFeedRate, 4, 1);
}

// ============================================================================
// Comments, messages, program end
// ============================================================================

TEST(InterpComment, CommentsBecomeCommentOps) {
  RUN_OK(r, "(Face the stock)\nG0 X1 ; rapid\nM2\n");
  EXPECT_EQ(r->kinds(), "comment comment traverse end");
  const auto c = r->all<canon::Comment>();
  EXPECT_EQ(c[0].text, "Face the stock");
  EXPECT_EQ(c[1].text, "rapid");
}

TEST(InterpComment, MessageIsANoteAndAComment) {
  RUN_OK(r, "G0 X1 (MSG,Load the vice jaws)\nM2\n");
  const auto notes = r->of_severity(core::Severity::Note);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(core::code_name(notes[0].code), core::code_name(Code::Message));
  EXPECT_EQ(notes[0].message, "Load the vice jaws");
  EXPECT_EQ(notes[0].loc.line, 1u);
  EXPECT_EQ(notes[0].loc.col, 7u);
  EXPECT_EQ(r->all<canon::Comment>()[0].text, "Load the vice jaws");
}

TEST(InterpComment, MessageKeywordIsCaseInsensitive) {
  RUN_OK(r, "(msg,hi)\nM2\n");
  EXPECT_EQ(r->of_severity(core::Severity::Note).size(), 1u);
}

TEST(InterpComment, OrdinaryCommentIsNotAMessage) {
  RUN_OK(r, "(message to self)\nM2\n");
  EXPECT_TRUE(r->of_severity(core::Severity::Note).empty());
}

TEST(InterpEnd, M2EndsTheProgramAndLaterBlocksDoNotRun) {
  RUN_OK(r, "G0 X1\nM2\nG0 X2\n");
  EXPECT_EQ(r->kinds(), "traverse end");
  EXPECT_TRUE(r->diags.all().empty());
}

TEST(InterpEnd, M30EndsTheProgram) {
  RUN_OK(r, "G0 X1\nM30\nG0 X2\n");
  EXPECT_EQ(r->kinds(), "traverse end");
}

TEST(InterpEnd, MissingEndIsAWarning) {
  RUN_OK(r, "G0 X1\nG0 X2\n");
  const auto w = r->of_severity(core::Severity::Warning);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(core::code_name(w[0].code), core::code_name(Code::NoProgramEnd));
  EXPECT_EQ(w[0].loc.line, 2u);
  EXPECT_EQ(r->kinds(), "traverse traverse");
}

TEST(InterpEnd, PercentLinesDelimitTheProgram) {
  RUN_OK(r, "%\nG0 X1\n%\nG0 X2\n");
  EXPECT_EQ(r->kinds(), "traverse");
  EXPECT_TRUE(r->diags.all().empty());
}

TEST(InterpEnd, M99InTheMainProgramEndsIt) {
  RUN_OK(r, "G0 X1\nM99\nG0 X2\n");
  EXPECT_EQ(r->kinds(), "traverse");
}

TEST(InterpEnd, ProgramStopsAreKeptAsComments) {
  RUN_OK(r, "M0\nM1\nM2\n");
  const auto c = r->all<canon::Comment>();
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c[0].text, "M0 (program stop)");
}

TEST(InterpEnd, SlashBlocksRunUnlessBlockDeleteIsOn) {
  // The operator's block delete switch is off by default, as in LinuxCNC.
  RUN_OK(all, "/G0 X5\nG0 X1\nM2\n");
  EXPECT_EQ(all->ends().size(), 2u);
  InterpOptions o;
  o.block_delete = true;
  RUN_OK(r, "/G0 X5\nG0 X1\n/M2\nM2\n", std::move(o));
  EXPECT_EQ(r->kinds(), "traverse end");
  EXPECT_EQ(r->ops().back().src.line, 4u);
}

TEST(InterpEnd, ByteOrderMarkIsAWarningAndSkipped) {
  RUN_OK(r, "\xEF\xBB\xBFG0 X1\nM2\n");
  const auto w = r->of_severity(core::Severity::Warning);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(core::code_name(w[0].code), core::code_name(Code::ByteOrderMark));
  EXPECT_EQ(r->kinds(), "traverse end");
}

TEST(InterpEnd, LineNumbersAreIgnored) {
  RUN_OK(r, "N10 G0 X1\nN20 M2\n");
  EXPECT_EQ(r->kinds(), "traverse end");
}

// ============================================================================
// Parameters
// ============================================================================

TEST(InterpParams, EveryValueOfABlockIsReadBeforeAnyIsWritten) {
  // RS274NGC 3.2.1: #2 takes the value #1 had before the block.
  RUN_OK(r, "#1=1\n#1=2 #2=#1\nG0 X#2\nM2\n");
  EXPECT_VEC(r->ends()[0], 1, 0, 0);
  EXPECT_DOUBLE_EQ(r->param(1), 2.0);
  EXPECT_DOUBLE_EQ(r->param(2), 1.0);
}

TEST(InterpParams, WordsReadTheValueBeforeTheBlocksAssignment) {
  RUN_OK(r, "#1=5 G0 X#1\nG0 Y#1\nM2\n");
  EXPECT_VEC(r->ends()[0], 0, 0, 0);
  EXPECT_VEC(r->ends()[1], 0, 5, 0);
}

TEST(InterpParams, NamedParameterNamesIgnoreCaseAndBlanks) {
  RUN_OK(r, "#<Depth Of Cut>=2\nG0 Z-#<depthofcut>\nM2\n");
  EXPECT_VEC(r->ends()[0], 0, 0, -2);
}

TEST(InterpParams, LocalsBelongToTheirCallGlobalsAreShared) {
  RUN_OK(r,
         "#<a>=1\n"
         "#<_g>=2\n"
         "#1=9\n"
         "o<s> sub\n"
         "  G0 X[EXISTS[#<a>]] Y#<_g> Z#1\n"
         "  #<a>=5\n"
         "  #<_g>=7\n"
         "o<s> endsub\n"
         "o<s> call [3]\n"
         "G0 X#<a> Y#<_g> Z#1\n"
         "M2\n");
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 2u);
  EXPECT_VEC(e[0], 0, 2, 3);
  EXPECT_VEC(e[1], 1, 7, 9);
}

TEST(InterpParams, CurrentPositionInProgramUnits) {
  RUN_OK(r,
         "G20\nG0 X1 Y2\n#1=#<_x>\n#2=#5421\n#3=#<_metric>\n#4=#<_imperial>\n"
         "G21\n#5=#<_metric>\n#6=#<_x>\nM2\n");
  EXPECT_DOUBLE_EQ(r->param(1), 1.0);
  EXPECT_DOUBLE_EQ(r->param(2), 2.0);
  EXPECT_DOUBLE_EQ(r->param(3), 0.0);
  EXPECT_DOUBLE_EQ(r->param(4), 1.0);
  EXPECT_DOUBLE_EQ(r->param(5), 1.0);
  EXPECT_NEAR(r->param(6), kInch, kTol);
}

TEST(InterpParams, PositionParametersAreInTheWorkSystem) {
  RUN_OK(r, "G10 L2 P1 X10\nG0 X2\n#1=#5420\n#2=#<_abs_x>\nM2\n");
  EXPECT_DOUBLE_EQ(r->param(1), 2.0);
  EXPECT_DOUBLE_EQ(r->param(2), 12.0);
}

TEST(InterpParams, ModalStateParameters) {
  RUN_OK(r,
         "G18 G91 G1 F10\n#1=#<_plane>\n#2=#<_incremental>\n#3=#<_absolute>\n"
         "#4=#<_motion_mode>\n#5=#<_feed>\nG20\nF4\n#6=#<_feed>\nM2\n");
  EXPECT_DOUBLE_EQ(r->param(1), 180.0);
  EXPECT_DOUBLE_EQ(r->param(2), 1.0);
  EXPECT_DOUBLE_EQ(r->param(3), 0.0);
  EXPECT_DOUBLE_EQ(r->param(4), 10.0);
  EXPECT_DOUBLE_EQ(r->param(5), 10.0);
  EXPECT_NEAR(r->param(6), 4.0, kTol);
}

TEST(InterpParams, ReadOnlyPredefinedParameterCannotBeAssigned) {
  auto r = run("G0 X1\n#<_x>=1\nM2\n");
  expect_error(*r, Code::ReadOnlyParameter, 2, 1);
}

TEST(InterpParams, UndefinedNamedParameterInAWord) {
  auto r = run("G0 X1\nG0 X#<nope>\nM2\n");
  expect_error(*r, Code::UndefinedParameter, 2, 5);
}

TEST(InterpParams, ParameterNumberOutOfRangeInAnAssignment) {
  auto r = run("#0=1\nM2\n");
  expect_error(*r, Code::ParameterOutOfRange, 1, 1);
  auto high = run("G0 X1\n  #5603=1\nM2\n");
  expect_error(*high, Code::ParameterOutOfRange, 2, 3);
}

TEST(InterpParams, DivisionByZeroInAWord) {
  auto r = run("G0 X1\nG0 X[1/0]\nM2\n");
  EXPECT_FALSE(r->ok);
  const auto errors = r->of_severity(core::Severity::Error);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(core::code_name(errors[0].code), core::code_name(Code::DivisionByZero));
  EXPECT_EQ(errors[0].loc.line, 2u);
}

// Regression (a bug the tests found, fixed): a parameter index that evaluates to NaN (inf - inf)
// passes parameter_index() and is read out of bounds. Expected: an error (E_PARAMETER_OUT_OF_RANGE)
// on line 1. Actual: undefined behaviour; the `usina trace` binary dies with SIGSEGV on this
// program.
TEST(InterpParams, NotANumberParameterIndexIsAnError) {
  auto r = run("#1=#[[10**400]-[10**400]]\nM2\n");
  EXPECT_FALSE(r->ok);
  EXPECT_EQ(r->of_severity(core::Severity::Error).size(), 1u);
}

// ============================================================================
// Control flow
// ============================================================================

std::string branch_program(int n) {
  return fmt::format(
      "#1={}\n"
      "o1 if [#1 EQ 1]\n  G0 X1\n"
      "o1 elseif [#1 EQ 2]\n  G0 X2\n"
      "o1 elseif [#1 EQ 3]\n  G0 X3\n"
      "o1 else\n  G0 X4\n"
      "o1 endif\n"
      "M2\n",
      n);
}

TEST(InterpControl, IfElseifElseRunsExactlyOneBranch) {
  for (int n = 1; n <= 5; ++n) {
    auto r = run(branch_program(n));
    ASSERT_TRUE(r->ok) << n;
    const auto e = r->ends();
    ASSERT_EQ(e.size(), 1u) << n;
    EXPECT_VEC(e[0], static_cast<double>(std::min(n, 4)), 0, 0);
  }
}

TEST(InterpControl, IfWithoutElseSkipsToEndif) {
  RUN_OK(r, "o1 if [0]\nG0 X1\no1 endif\nG0 X2\nM2\n");
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 1u);
  EXPECT_VEC(e[0], 2, 0, 0);
}

TEST(InterpControl, WhileRunsWhileTheConditionHolds) {
  RUN_OK(r, "#1=0\no1 while [#1 LT 3]\nG0 X#1\n#1=[#1+1]\no1 endwhile\nM2\n");
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 3u);
  EXPECT_VEC(e[2], 2, 0, 0);
}

TEST(InterpControl, WhileFalseAtFirstRunsNothing) {
  RUN_OK(r, "o1 while [0]\nG0 X1\no1 endwhile\nM2\n");
  EXPECT_TRUE(r->ends().empty());
}

TEST(InterpControl, DoWhileRunsTheBodyAtLeastOnce) {
  RUN_OK(r, "#1=5\no1 do\nG0 X#1\n#1=[#1+1]\no1 while [#1 LT 3]\nM2\n");
  EXPECT_EQ(r->ends().size(), 1u);
  RUN_OK(three, "#1=0\no1 do\nG0 X#1\n#1=[#1+1]\no1 while [#1 LT 3]\nM2\n");
  EXPECT_EQ(three->ends().size(), 3u);
}

TEST(InterpControl, RepeatRunsTheBodyNTimes) {
  RUN_OK(r, "o1 repeat [3]\nG91 G0 X1\no1 endrepeat\nM2\n");
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 3u);
  EXPECT_VEC(e[2], 3, 0, 0);
}

TEST(InterpControl, RepeatZeroTimesRunsNothing) {
  RUN_OK(r, "o1 repeat [0]\nG0 X1\no1 endrepeat\nG0 X2\nM2\n");
  EXPECT_EQ(r->ends().size(), 1u);
}

TEST(InterpControl, BreakLeavesTheLoop) {
  RUN_OK(r,
         "#1=0\n"
         "o1 while [1]\n"
         "  #1=[#1+1]\n"
         "  o2 if [#1 GT 2]\n"
         "    o1 break\n"
         "  o2 endif\n"
         "  G0 X#1\n"
         "o1 endwhile\n"
         "G0 Y9\n"
         "M2\n");
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 3u);
  EXPECT_VEC(e[1], 2, 0, 0);
  EXPECT_VEC(e[2], 2, 9, 0);
}

TEST(InterpControl, BreakLeavesARepeat) {
  RUN_OK(r,
         "o1 repeat [10]\nG91 G0 X1\no2 if [#<_x> GE 2]\no1 break\no2 endif\no1 endrepeat\nM2\n");
  EXPECT_EQ(r->ends().size(), 2u);
}

TEST(InterpControl, ContinueSkipsTheRestOfTheBody) {
  RUN_OK(r,
         "#1=0\n"
         "o1 while [#1 LT 4]\n"
         "  #1=[#1+1]\n"
         "  o2 if [#1 EQ 2]\n"
         "    o1 continue\n"
         "  o2 endif\n"
         "  G0 X#1\n"
         "o1 endwhile\n"
         "M2\n");
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 3u);
  EXPECT_VEC(e[0], 1, 0, 0);
  EXPECT_VEC(e[1], 3, 0, 0);
  EXPECT_VEC(e[2], 4, 0, 0);
}

TEST(InterpControl, ContinueInADoWhileTestsTheCondition) {
  RUN_OK(r,
         "#1=0\n"
         "o1 do\n"
         "  #1=[#1+1]\n"
         "  o2 if [#1 EQ 1]\n"
         "    o1 continue\n"
         "  o2 endif\n"
         "  G0 X#1\n"
         "o1 while [#1 LT 3]\n"
         "M2\n");
  EXPECT_EQ(r->ends().size(), 2u);
}

TEST(InterpControl, NestedLoopsEachRunFully) {
  RUN_OK(r,
         "#1=0\n"
         "o1 while [#1 LT 3]\n"
         "  #2=0\n"
         "  o2 while [#2 LT 4]\n"
         "    G0 X#1 Y#2\n"
         "    #2=[#2+1]\n"
         "  o2 endwhile\n"
         "  #1=[#1+1]\n"
         "o1 endwhile\n"
         "M2\n");
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 12u);
  EXPECT_VEC(e[11], 2, 3, 0);
}

TEST(InterpControl, LoopLimitCountsOneRunOfAWhileLoop) {
  // 3 x 4 inner iterations in all, but no single run of a loop exceeds 5.
  InterpOptions o;
  o.max_loop_iterations = 5;
  RUN_OK(r,
         "#1=0\n"
         "o1 while [#1 LT 3]\n"
         "  #2=0\n"
         "  o2 while [#2 LT 4]\n"
         "    #2=[#2+1]\n"
         "  o2 endwhile\n"
         "  #1=[#1+1]\n"
         "o1 endwhile\n"
         "M2\n",
         std::move(o));
}

// Regression (a bug the tests found, fixed): the loop counter of `repeat` is never reset when the
// loop finishes normally (EndRepeat pops loops_ but does not erase iterations_), so an inner repeat
// counts its iterations over every run of the outer loop. Expected: 10 x 10 nested repeats with
// max_loop_iterations = 50 run (no single run exceeds 10). Actual: E_TOO_MANY_ITERATIONS on the
// inner endrepeat once the total passes 50. `while` loops reset correctly.
TEST(InterpControl, LoopLimitCountsOneRunOfARepeat) {
  InterpOptions o;
  o.max_loop_iterations = 50;
  RUN_OK(r, "o1 repeat [10]\no2 repeat [10]\nG0 X1\no2 endrepeat\no1 endrepeat\nM2\n",
         std::move(o));
  EXPECT_EQ(r->ends().size(), 100u);
}

// Regression (a bug the tests found, fixed): as for repeat: a do-while's counter (keyed by its
// `do`) is not reset when its closing `while` is false. Expected: an inner do-while of 10 runs
// inside an outer loop of 10 with max_loop_iterations = 50 runs. Actual:
// E_TOO_MANY_ITERATIONS.
TEST(InterpControl, LoopLimitCountsOneRunOfADoWhile) {
  InterpOptions o;
  o.max_loop_iterations = 50;
  RUN_OK(r,
         "#1=0\n"
         "o1 while [#1 LT 10]\n"
         "  #2=0\n"
         "  o2 do\n"
         "    #2=[#2+1]\n"
         "  o2 while [#2 LT 10]\n"
         "  #1=[#1+1]\n"
         "o1 endwhile\n"
         "M2\n",
         std::move(o));
}

// Regression (a bug the tests found, fixed): `break` erases the counter of the break statement's
// own index entry, not the loop's, so a while loop left by break keeps its count for its next run.
// Expected: an inner while left by break after 9 runs, inside an outer loop of 10, with
// max_loop_iterations = 50, runs. Actual: E_TOO_MANY_ITERATIONS.
TEST(InterpControl, LoopLimitCountsOneRunOfAWhileLeftByBreak) {
  InterpOptions o;
  o.max_loop_iterations = 50;
  RUN_OK(r,
         "#1=0\n"
         "o1 while [#1 LT 10]\n"
         "  #2=0\n"
         "  o2 while [1]\n"
         "    #2=[#2+1]\n"
         "    o3 if [#2 GE 9]\n"
         "      o2 break\n"
         "    o3 endif\n"
         "  o2 endwhile\n"
         "  #1=[#1+1]\n"
         "o1 endwhile\n"
         "M2\n",
         std::move(o));
}

TEST(InterpControl, TooManyIterationsStopsARunawayLoop) {
  InterpOptions o;
  o.max_loop_iterations = 5;
  auto r = run("o1 while [1]\n  G91 G0 X1\no1 endwhile\nM2\n", std::move(o));
  expect_error(*r, Code::TooManyIterations, 3, 1);
  EXPECT_EQ(r->ends().size(), 6u);
}

TEST(InterpControl, TooManyIterationsOfARepeat) {
  InterpOptions o;
  o.max_loop_iterations = 3;
  auto r = run("o1 repeat [100]\no1 endrepeat\nM2\n", std::move(o));
  expect_error(*r, Code::TooManyIterations, 2, 1);
}

TEST(InterpControl, TooManyIterationsOfADoWhile) {
  InterpOptions o;
  o.max_loop_iterations = 3;
  auto r = run("o1 do\no1 while [1]\nM2\n", std::move(o));
  expect_error(*r, Code::TooManyIterations, 2, 1);
}

// --- subroutines ------------------------------------------------------------

TEST(InterpSub, CallWithArgumentsAndReturnValue) {
  RUN_OK(r,
         "o<double> sub\n"
         "  o<double> return [#1*2]\n"
         "o<double> endsub\n"
         "o<double> call [21]\n"
         "G0 X#<_value>\n"
         "#1=#<_value_returned>\n"
         "M2\n");
  EXPECT_VEC(r->ends()[0], 42, 0, 0);
  EXPECT_DOUBLE_EQ(r->param(1), 1.0);
}

TEST(InterpSub, EndsubWithValueReturnsIt) {
  RUN_OK(r, "o100 sub\no100 endsub [7]\no100 call\nG0 X#<_value>\nM2\n");
  EXPECT_VEC(r->ends()[0], 7, 0, 0);
}

TEST(InterpSub, ArgumentsAreHash1ToHash30AndRestoredAfter) {
  RUN_OK(r,
         "#1=100 #2=200 #3=300\n"
         "o1 sub\n  G0 X#1 Y#2 Z#3\no1 endsub\n"
         "o1 call [1] [2]\n"
         "G0 X#1 Y#2 Z#3\n"
         "M2\n");
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 2u);
  EXPECT_VEC(e[0], 1, 2, 0);
  EXPECT_VEC(e[1], 100, 200, 300);
}

TEST(InterpSub, SubroutineDefinedAfterItsCall) {
  RUN_OK(r, "o<later> call [4]\nM2\no<later> sub\nG0 X#1\no<later> endsub\n");
  EXPECT_VEC(r->ends()[0], 4, 0, 0);
}

TEST(InterpSub, DefinitionIsSkippedWhenReached) {
  RUN_OK(r, "o1 sub\nG0 X9\no1 endsub\nG0 X1\nM2\n");
  EXPECT_EQ(r->ends().size(), 1u);
  EXPECT_VEC(r->ends()[0], 1, 0, 0);
}

TEST(InterpSub, OpsOfASubroutinePointIntoIt) {
  RUN_OK(r, "o1 sub\n  G0 X9\no1 endsub\no1 call\nM2\n");
  const auto t = r->ops_of<Traverse>();
  ASSERT_EQ(t.size(), 1u);
  EXPECT_EQ(t[0]->src.line, 2u);
  EXPECT_EQ(t[0]->src.col, 3u);
}

TEST(InterpSub, RecursiveFactorial) {
  RUN_OK(r,
         "o<fact> sub\n"
         "  o<base> if [#1 LE 1]\n"
         "    o<fact> return [1]\n"
         "  o<base> endif\n"
         "  o<fact> call [#1-1]\n"
         "  o<fact> return [#1*#<_value>]\n"
         "o<fact> endsub\n"
         "o<fact> call [5]\n"
         "#1=#<_value>\n"
         "M2\n");
  EXPECT_DOUBLE_EQ(r->param(1), 120.0);
}

TEST(InterpSub, CallByNumberFromAParameter) {
  RUN_OK(r, "#5=200\no200 sub\nG0 X2\no200 endsub\no#5 call\nM2\n");
  EXPECT_VEC(r->ends()[0], 2, 0, 0);
}

TEST(InterpSub, CallLevelInsideASubroutine) {
  RUN_OK(r, "o1 sub\n#<_lvl>=#<_call_level>\no1 endsub\no1 call\n#1=#<_lvl>\nM2\n");
  EXPECT_DOUBLE_EQ(r->param(1), 1.0);
}

TEST(InterpSub, SubroutineInItsOwnFileOnTheSearchPath) {
  TempDir dir;
  const std::string file = dir.write("peck.ngc", "o<peck> sub\n  G0 X#1\no<peck> endsub\n");
  InterpOptions o;
  o.subroutine_path = {"/nonexistent/usina", dir.path()};
  RUN_OK(r, "o<peck> call [4]\no<peck> call [5]\nM2\n", std::move(o));
  const auto t = r->ops_of<Traverse>();
  ASSERT_EQ(t.size(), 2u);
  EXPECT_VEC(std::get<Traverse>(t[1]->kind).to, 5, 0, 0);
  // The op points into the subroutine's file, line 2.
  const core::SourceFile* f = r->sources.get(t[0]->src.file);
  ASSERT_NE(f, nullptr);
  EXPECT_EQ(f->name(), file);
  EXPECT_EQ(t[0]->src.line, 2u);
  EXPECT_EQ(r->sources.size(), 2u) << "the file is loaded once";
}

TEST(InterpSub, FileWithoutSubLinesIsTheSubroutineBody) {
  TempDir dir;
  dir.write("corner.ngc", "G0 X#1 Y#2\n");
  InterpOptions o;
  o.subroutine_path = {dir.path()};
  RUN_OK(r, "o<corner> call [1] [2]\nG0 Z3\nM2\n", std::move(o));
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 2u);
  EXPECT_VEC(e[0], 1, 2, 0);
  EXPECT_VEC(e[1], 1, 2, 3);
}

TEST(InterpSub, SubroutineFileMayCallSubroutinesOfTheMainProgram) {
  TempDir dir;
  dir.write("outer.ngc", "o<outer> sub\n  o<inner> call\no<outer> endsub\n");
  InterpOptions o;
  o.subroutine_path = {dir.path()};
  RUN_OK(r, "o<inner> sub\nG0 X8\no<inner> endsub\no<outer> call\nM2\n", std::move(o));
  EXPECT_VEC(r->ends()[0], 8, 0, 0);
}

TEST(InterpSub, SubroutineFileWithoutEndsubIsAnError) {
  TempDir dir;
  const std::string file = dir.write("open.ngc", "o<open> sub\nG0 X1\n");
  InterpOptions o;
  o.subroutine_path = {dir.path()};
  auto r = run("o<open> call\nM2\n", std::move(o));
  EXPECT_FALSE(r->ok);
  const auto errors = r->of_severity(core::Severity::Error);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(core::code_name(errors[0].code), core::code_name(Code::UnclosedBlock));
  EXPECT_EQ(r->sources.get(errors[0].loc.file)->name(), file);
}

TEST(InterpSub, UnknownSubroutine) {
  auto r = run("G0 X1\n  o<nothere> call\nM2\n");
  expect_error(*r, Code::UnknownSubroutine, 2, 3);
}

TEST(InterpSub, ShellSyntaxInANameIsNeverRun) {
  // LinuxCNC expands o<name> file names with wordexp(), which runs $(...).
  // usina never may: the name is only a file name.
  const char* marker = "/tmp/usina_pwned";
  ::unlink(marker);
  TempDir dir;
  InterpOptions o;
  o.subroutine_path = {dir.path(), "."};
  auto r = run("o<$(touch /tmp/usina_pwned)> call\nM2\n", std::move(o));
  expect_error(*r, Code::BadSubroutineName, 1, 1);  // the '/' of the path

  struct stat st {};

  EXPECT_NE(::stat(marker, &st), 0) << marker << " was created";
  auto backticks = run("o<`touch /tmp/usina_pwned`> call\nM2\n");
  expect_error(*backticks, Code::BadSubroutineName, 1, 1);
  EXPECT_NE(::stat(marker, &st), 0) << marker << " was created";
}

TEST(InterpSub, NameWithoutSlashButWithShellSyntaxIsOnlyAFileName) {
  TempDir dir;
  // A file literally named so is found; nothing is expanded.
  dir.write("$(id).ngc", "G0 X3\n");
  InterpOptions o;
  o.subroutine_path = {dir.path()};
  RUN_OK(r, "o<$(id)> call\nM2\n", std::move(o));
  EXPECT_VEC(r->ends()[0], 3, 0, 0);
}

TEST(InterpSub, NamesCannotLeaveTheSearchPath) {
  TempDir dir;
  dir.write(".hidden.ngc", "G0 X1\n");
  InterpOptions o;
  o.subroutine_path = {dir.path()};
  auto r = run("o<.hidden> call\nM2\n", o);
  expect_error(*r, Code::BadSubroutineName, 1, 1);
  auto up = run("o<../etc/passwd> call\nM2\n", o);
  expect_error(*up, Code::BadSubroutineName, 1, 1);
}

TEST(InterpSub, RecursionTooDeep) {
  InterpOptions o;
  o.max_call_depth = 10;
  auto r = run("o<r> sub\n  o<r> call\no<r> endsub\no<r> call\nM2\n", std::move(o));
  expect_error(*r, Code::RecursionTooDeep, 2, 3);
}

TEST(InterpSub, AtMostThirtyArguments) {
  std::string call = "o1 call";
  for (int i = 0; i < 31; ++i)
    call += " [1]";
  auto r = run("o1 sub\no1 endsub\n" + call + "\nM2\n");
  expect_error(*r, Code::BadOWord, 3, 1);
}

TEST(InterpSub, SubWithoutEndsub) {
  auto r = run("G0 X1\no<s> sub\nG0 X2\nM2\n");
  expect_error(*r, Code::UnclosedBlock, 2, 1);
}

TEST(InterpSub, EndsubOutsideACall) {
  auto r = run("G0 X1\no<s> endsub\nM2\n");
  expect_error(*r, Code::UnmatchedControl, 2, 1);
  auto ret = run("o<s> return\nM2\n");
  expect_error(*ret, Code::UnmatchedControl, 1, 1);
}

// --- Fanuc-style subprograms ------------------------------------------------

TEST(InterpFanuc, M98RunsTheSubprogramLTimes) {
  RUN_OK(r, "M98 P100 L2\nG90 G0 Y5\nM30\nO100\nG91 G0 X1\nM99\n");
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 3u);
  EXPECT_VEC(e[0], 1, 0, 0);
  EXPECT_VEC(e[1], 2, 0, 0);
  EXPECT_VEC(e[2], 2, 5, 0);
}

TEST(InterpFanuc, M98WithoutLRunsOnce) {
  RUN_OK(r, "M98 P7\nM30\nO7 (subprogram)\nG0 X1\nM99\n");
  EXPECT_EQ(r->ends().size(), 1u);
}

TEST(InterpFanuc, M98ParametersAreNotScoped) {
  RUN_OK(r, "#1=1\nM98 P7\nG0 X#1\nM30\nO7\n#1=6\nM99\n");
  EXPECT_VEC(r->ends()[0], 6, 0, 0);
}

TEST(InterpFanuc, M98WithoutP) {
  auto r = run("G0 X1\nG0 X2 M98\nM30\n");
  expect_error(*r, Code::MissingWord, 2, 7);
}

TEST(InterpFanuc, M98OfAMissingProgram) {
  auto r = run("M98 P200\nM30\n");
  expect_error(*r, Code::UnknownSubroutine, 1, 5);
}

// --- unclosed and unmatched control statements -----------------------------

// Control statements left open, closed without an opening, or failing:
// each program stops at its one error.
constexpr ErrorCase kControlErrors[] = {
    {"if without endif", "G0 X1\no1 if [0]\nG0 X2\nM2\n", Code::UnclosedBlock, 2, 1},
    {"else of a taken branch without endif", "o1 if [1]\nG0 X1\no1 else\nG0 X2\nM2\n",
     Code::UnclosedBlock, 3, 1},
    {"while without endwhile", "o1 while [0]\nG0 X1\nM2\n", Code::UnclosedBlock, 1, 1},
    {"repeat without endrepeat", "o1 repeat [2]\nG0 X1\nM2\n", Code::UnclosedBlock, 1, 1},
    {"break outside a loop", "G0 X1\no1 break\nM2\n", Code::UnclosedBlock, 2, 1},
    // Regression (a bug the tests found, fixed): a closing statement with no opening one is not
    // E_UNMATCHED_CONTROL: `o1 endwhile` alone is reported as E_UNCLOSED_CONTROL_BLOCK ("o1
    // endwhile has no while"), and `o1 else` / `o1 endif` without an `o1 if` are accepted
    // silently (else jumps to the endif; endif does nothing). Expected:
    // E_UNMATCHED_CONTROL at the stray statement in each case.
    {"a stray closing statement is unmatched", "G0 X1\no1 endwhile\nM2\n", Code::UnmatchedControl,
     2, 1},
    {"a stray closing statement is unmatched", "o1 endrepeat\nM2\n", Code::UnmatchedControl, 1, 1},
    {"a stray closing statement is unmatched", "o1 else\nG0 X1\no1 endif\nM2\n",
     Code::UnmatchedControl, 1, 1},
    {"a stray closing statement is unmatched", "o1 endif\nM2\n", Code::UnmatchedControl, 1, 1},
    {"an error in a condition is reported", "o1 if [#<undefined> GT 1]\no1 endif\nM2\n",
     Code::UndefinedParameter, 1, 8},
    {"an O-word after other text is a syntax error", "G0 X1 o1 if [1]\nM2\n", Code::MisplacedOWord,
     1, 7},
};

TEST(InterpControl, UnclosedUnmatchedAndFailedControlStatementsAreErrors) {
  expect_errors(kControlErrors);
}

// ============================================================================
// Block checks: every error path with its code, line and column
// ============================================================================

TEST(InterpCheck, SyntaxErrorStopsTheRunWithItsPlace) {
  auto r = run("G0 X1\nG1 (oops\nG0 X2\nM2\n");
  expect_error(*r, Code::UnclosedComment, 2, 4);
  EXPECT_EQ(r->kinds(), "traverse");
}

// Bad blocks: each program stops at its one error, with the code, line and
// column the row gives.
constexpr ErrorCase kBlockErrors[] = {
    {"unknown G code", "G0 X1\nG0 G12 X2\nM2\n", Code::UnknownGCode, 2, 4},
    {"G code with too many decimals", "G1.55\nM2\n", Code::UnknownGCode, 1, 1},
    {"negative G code", "G-1\nM2\n", Code::UnknownGCode, 1, 1},
    {"unknown M code", "M3 M200\nM2\n", Code::UnknownMCode, 1, 4},
    {"fractional M code", "M3.5\nM2\n", Code::UnknownMCode, 1, 1},
    {"two motion codes", "G0 G1 X1 F1\nM2\n", Code::ModalGroupConflict, 1, 4},
    {"two codes of another modal group", "G20 G21\nM2\n", Code::ModalGroupConflict, 1, 5},
    {"two codes of another modal group", "G17 G18\nM2\n", Code::ModalGroupConflict, 1, 5},
    {"two codes of another modal group", "G90 G91\nM2\n", Code::ModalGroupConflict, 1, 5},
    {"two codes of another modal group", "G54 G55\nM2\n", Code::ModalGroupConflict, 1, 5},
    {"two codes of another modal group", "M3 M5\nM2\n", Code::ModalGroupConflict, 1, 4},
    {"two codes of another modal group", "M7 M9\nM2\n", Code::ModalGroupConflict, 1, 4},
    {"too many user M codes", "M100 M101 M102 M103 M104\nM2\n", Code::ModalGroupConflict, 1, 21},
    {"repeated word", "G0 X1 X2\nM2\n", Code::RepeatedWord, 1, 7},
    // A centre word of the wrong plane is an error, at the word: K in a G17
    // arc, J in G18, I in G19 (LinuxCNC interp_convert.cc, convert_arc:
    // NCE_K_WORD_GIVEN_FOR_ARC_IN_XY_PLANE and the J/XZ and I/YZ cases).
    {"a centre word of another plane is unused", "G1 F100\nG17 G2 X10 I5 K1\nM2\n",
     Code::UnusedWord, 2, 15},
    {"a centre word of another plane is unused", "G1 F100\nG18 G2 X10 I5 J1\nM2\n",
     Code::UnusedWord, 2, 15},
    {"a centre word of another plane is unused", "G1 F100\nG19 G2 Y10 J5 I1\nM2\n",
     Code::UnusedWord, 2, 15},
    {"axis words with G80", "G80 X1\nM2\n", Code::AxisWordsConflict, 1, 5},
    // LinuxCNC starts in G80: a bare X is an error until G0/G1 is given.
    {"axis words before any motion code", "X1\nM2\n", Code::AxisWordsConflict, 1, 1},
    {"motion and a non-modal code both using axes", "G92 G1 X1 F1\nM2\n", Code::AxisWordsConflict,
     1, 1},
    {"arc radius mismatch", "G1 F100\nG2 X10 Y0 I4\nM2\n", Code::ArcRadiusMismatch, 2, 1},
    {"arc radius too small", "G1 F100\nG2 X10 R4\nM2\n", Code::ArcRadiusTooSmall, 2, 8},
    {"an R-format full circle", "G1 F100\nG2 X0 Y0 R5\nM2\n", Code::ArcZeroLength, 2, 10},
    {"arc with both R and centre", "G1 F100\nG2 X10 R5 I5\nM2\n", Code::ArcMissingCenter, 2, 8},
    {"arc without centre", "G1 F100\n  G2 X10\nM2\n", Code::ArcMissingCenter, 2, 3},
    {"arc with its centre at the start", "G1 F100\nG2 X0 Y0 I0 J0\nM2\n", Code::ArcZeroLength, 2,
     1},
    {"arc turns P must be a positive integer", "G1 F100\nG2 X0 I5 P0\nM2\n", Code::BadWordValue, 2,
     10},
    {"arc turns P must be a positive integer", "G1 F100\nG2 X0 I5 P1.5\nM2\n", Code::BadWordValue,
     2, 10},
    {"no feed rate", "G1 X1\nM2\n", Code::NoFeedRate, 1, 1},
    {"no feed rate", "G0 X1\nG3 X0 Y0 I5\nM2\n", Code::NoFeedRate, 2, 1},
    {"negative feed or speed", "G1 X1 F-1\nM2\n", Code::BadWordValue, 1, 7},
    {"negative feed or speed", "M3 S-100\nM2\n", Code::BadWordValue, 1, 4},
    {"tool number must be a non-negative integer", "T1.5\nM2\n", Code::BadWordValue, 1, 1},
    {"tool number must be a non-negative integer", "G0 X1 T-1\nM2\n", Code::BadWordValue, 1, 7},
    {"M6 without a tool", "G0 X1\nM6\nM2\n", Code::MissingWord, 2, 1},
    {"M61 without Q", "M61\nM2\n", Code::MissingWord, 1, 1},
    {"dwell without time", "G4\nM2\n", Code::MissingWord, 1, 1},
    {"dwell without time", "G0 X1 G4 P-1\nM2\n", Code::MissingWord, 1, 7},
    {"G10 without L or P, or with a bad one", "G10 P1 X1\nM2\n", Code::MissingWord, 1, 1},
    {"G10 without L or P, or with a bad one", "G10 L2 X1\nM2\n", Code::MissingWord, 1, 1},
    {"G10 without L or P, or with a bad one", "G10 L2 P10 X1\nM2\n", Code::BadWordValue, 1, 8},
    {"G10 without L or P, or with a bad one", "G10 L2 P1.5 X1\nM2\n", Code::BadWordValue, 1, 8},
    {"G10 without L or P, or with a bad one", "G10 L2 P-1 X1\nM2\n", Code::BadWordValue, 1, 8},
    {"G10 without L or P, or with a bad one", "G10 L3 P1 X1\nM2\n", Code::BadWordValue, 1, 5},
    {"G92 and G52 need an axis", "G92\nM2\n", Code::MissingWord, 1, 1},
    {"G92 and G52 need an axis", "G0 X1\nG52\nM2\n", Code::MissingWord, 2, 1},
    {"G43 with an unknown tool", "G43 H99\nM2\n", Code::UnknownTool, 1, 5, true},
    {"cutter compensation errors", "G41 D99\nM2\n", Code::UnknownTool, 1, 5, true},
    {"cutter compensation errors", "G41.1\nM2\n", Code::MissingWord, 1, 1},
    {"cutter compensation errors", "G19\nG41 D1\nM2\n", Code::CompNotAllowed, 2, 1, true},
    {"cutter compensation errors", "G41 D1\nG42 D1\nM2\n", Code::CompNotAllowed, 2, 1, true},
    {"a probe needs a feed", "G38.2 Z-5\nM2\n", Code::NoFeedRate, 1, 1},
    {"M72 restore without M70 save", "G0 X1\nM72\nM2\n", Code::NotAllowedInMode, 2, 1},
    {"M73 auto-restore outside a subroutine", "M73\nM2\n", Code::NotAllowedInMode, 1, 1},
};

TEST(InterpCheck, EachBadBlockIsOneErrorAtItsWord) {
  expect_errors(kBlockErrors);
}

TEST(InterpCheck, UnusedWordsAreErrors) {
  struct Case {
    const char* text;
    std::uint32_t col;
  };

  const Case cases[] = {
      {"G0 X1 I2", 7}, {"G0 X1 J2", 7}, {"G0 X1 K2", 7}, {"G0 X1 R2", 7}, {"G0 X1 P2", 7},
      {"G0 X1 Q2", 7}, {"G0 X1 L2", 7}, {"G0 X1 D2", 7}, {"G0 X1 H2", 7}, {"G0 X1 E2", 7},
  };
  for (const Case& c : cases) {
    auto r = run(std::string(c.text) + "\nM2\n");
    SCOPED_TRACE(c.text);
    expect_error(*r, Code::UnusedWord, 1, c.col);
  }
}

TEST(InterpCheck, ArcEndSlightlyOffTheCircleIsAccepted) {
  // LinuxCNC accepts a small difference of radii (0.02 mm here).
  RUN_OK(r, "G1 F100\nG2 X10.01 Y0 I5\nM2\n");
  EXPECT_EQ(r->all<Arc>().size(), 1u);
}

TEST(InterpCheck, G43ForTheEmptySpindleIsNoOffset) {
  RUN_OK(r, "G43\n#1=#<_tool_offset>\nM2\n", with_tools());
  EXPECT_DOUBLE_EQ(r->param(1), 0.0);
}

TEST(InterpCheck, ProbeReachesItsTargetAndRecordsIt) {
  RUN_OK(r, "G20\nG38.2 Z-1 F10\nM2\n");
  const auto p = r->all<canon::Probe>();
  ASSERT_EQ(p.size(), 1u);
  EXPECT_VEC(p[0].to, 0, 0, -kInch);
  // As LinuxCNC's stand-alone interpreter: the probe stops 0.01 program
  // units short of its target and is not tripped.
  EXPECT_NEAR(r->param(5063), -0.99, kTol);
  EXPECT_DOUBLE_EQ(r->param(5070), 0.0);
}

TEST(InterpCheck, ModalStateSaveAndRestore) {
  RUN_OK(r, "M70\nG20 G91\nM72\n#1=#<_metric>\n#2=#<_absolute>\nM2\n");
  EXPECT_DOUBLE_EQ(r->param(1), 1.0);
  EXPECT_DOUBLE_EQ(r->param(2), 1.0);
}

TEST(InterpCheck, ErrorStopsTheRunAndNothingAfterItIsEmitted) {
  auto r = run("G0 X1\nG1 X2\nG0 X3\nM2\n");
  EXPECT_FALSE(r->ok);
  EXPECT_EQ(r->kinds(), "traverse");
  EXPECT_EQ(r->interp->state().pos[0], 1.0);
}

// Regression (a bug the tests found, fixed): DESIGN.md and state.hpp: "the block works on a copy
// that replaces the state only when the block succeeded, so a failed block changes nothing".
// Execute writes state_ directly, so the G20 of a block whose motion then
// fails stays in effect. Expected: units still mm after the failed block.
// Actual: inch.
TEST(InterpCheck, FailedBlockChangesNoModalState) {
  auto r = run("G20 G91 G1 X1\nM2\n");
  EXPECT_FALSE(r->ok);
  EXPECT_EQ(r->interp->state().units, core::LengthUnit::Mm);
  EXPECT_FALSE(r->interp->state().incremental);
}

// --- splines: their errors --------------------------------------------------

// G5, G5.1 and G5.2 blocks that are refused.
constexpr ErrorCase kSplineErrors[] = {
    {"G5 outside the XY plane", "G1 F10\nG18 G5 X1 I1 J1 P1 Q1\nM2\n", Code::NotAllowedInMode, 2,
     1},
    {"G5 with Z", "G1 F10\nG5 X1 Z1 I1 J1 P1 Q1\nM2\n", Code::SplineBadValue, 2, 1},
    {"G5 needs P and Q", "G1 F10\nG5 X1 I1 J1 P1\nM2\n", Code::MissingWord, 2, 1},
    {"G5 needs I and J together", "G1 F10\nG5 X1 I1 P1 Q1\nM2\n", Code::MissingWord, 2, 1},
    {"G5 without IJ must follow another G5", "G1 F10\nG5 X1 P1 Q1\nM2\n", Code::MissingWord, 2, 1},
    {"G5.1 needs I or J", "G1 F10\nG5.1 X1\nM2\n", Code::MissingWord, 2, 1},
    {"G5.2 with a negative weight", "G1 F10\nG5.2 X1 Y1 P-1 L3\nM2\n", Code::SplineBadValue, 2, 12},
};

TEST(InterpSpline, BadSplinesAreErrors) {
  expect_errors(kSplineErrors);
}

TEST(InterpSpline, G5EndsAtItsEndPoint) {
  RUN_OK(r, "G1 F10\nG5 X10 Y0 I3 J3 P-3 Q3\nM2\n");
  EXPECT_VEC(r->ends().back(), 10, 0, 0);
  EXPECT_VEC(xyz(r->interp->state().pos), 10, 0, 0);
}

// ============================================================================
// Realistic programs from tests/programs/rs274ngc
// ============================================================================

std::unique_ptr<Run> run_file(const std::string& name, InterpOptions opts = {}) {
  auto r = std::make_unique<Run>();
  std::string error;
  const std::string path = std::string(USINA_TEST_DIR) + "/programs/rs274ngc/" + name;
  auto f = core::SourceFile::open(path, error);
  EXPECT_NE(f, nullptr) << path << ": " << error;
  if (f == nullptr) return r;
  const std::uint32_t id = r->sources.add(std::move(f));
  opts.subroutine_path.push_back(std::string(USINA_TEST_DIR) + "/programs/rs274ngc");
  r->interp = std::make_unique<Interpreter>(r->sources, std::move(opts), r->path, r->diags);
  r->ok = r->interp->run(id);
  return r;
}

TEST(InterpPrograms, FaceMillCoversThePlate) {
  auto r = run_file("face_mill.ngc", with_tools());
  ASSERT_TRUE(r->ok) << (r->diags.all().empty() ? "" : r->diags.all()[0].message);
  EXPECT_EQ(r->diags.error_count(), 0);
  const auto f = r->all<Feed>();
  // 100 x 60 plate, 10 mm step over from Y-5 to Y65: 8 passes, each a cut
  // and a step, the last without a step.
  ASSERT_FALSE(f.empty());
  double min_y = 1e9;
  double max_y = -1e9;
  for (const Feed& m : f) {
    min_y = std::min(min_y, m.to.y);
    max_y = std::max(max_y, m.to.y);
    EXPECT_NEAR(m.to.z, -0.5, kTol);
  }
  EXPECT_NEAR(min_y, -5, kTol);
  EXPECT_NEAR(max_y, 65, kTol);
  EXPECT_EQ(r->all<canon::ToolChange>().size(), 1u);
  EXPECT_EQ(r->kinds().substr(r->kinds().size() - 3), "end");
}

TEST(InterpPrograms, BoltCircleDrillsEveryHole) {
  auto r = run_file("bolt_circle.ngc");
  ASSERT_TRUE(r->ok) << (r->diags.all().empty() ? "" : r->diags.all()[0].message);
  // Two circles: 6 holes of radius 40 about (0,0), 4 of radius 15 about (100,0).
  std::vector<Vec3> bottoms;
  for (const Feed& m : r->all<Feed>()) {
    if (m.to.z < -9) bottoms.push_back(m.to);
  }
  ASSERT_EQ(bottoms.size(), 10u);
  for (int i = 0; i < 6; ++i) {
    const double a = core::deg_to_rad(30.0 + 60.0 * i);
    EXPECT_VEC(bottoms[static_cast<std::size_t>(i)], 40 * std::cos(a), 40 * std::sin(a), -12);
  }
  for (int i = 0; i < 4; ++i) {
    const double a = core::deg_to_rad(90.0 * i);
    EXPECT_VEC(bottoms[static_cast<std::size_t>(6 + i)], 100 + 15 * std::cos(a), 15 * std::sin(a),
               -10);
  }
}

TEST(InterpPrograms, InchKeyholeSlotWithHelicalEntry) {
  auto r = run_file("keyhole_inch.ngc");
  ASSERT_TRUE(r->ok) << (r->diags.all().empty() ? "" : r->diags.all()[0].message);
  const auto a = r->all<Arc>();
  ASSERT_EQ(a.size(), 4u);
  // The helix: two turns down to Z-0.25 in about (1, 1) in.
  EXPECT_EQ(a[0].turn, 2);
  EXPECT_VEC(a[0].center, kInch, kInch, 0.05 * kInch);
  EXPECT_NEAR(a[0].to.z, -0.25 * kInch, kTol);
  // The slot's far end: a half circle of R0.25 in clockwise.
  EXPECT_EQ(a[2].turn, -1);
  EXPECT_VEC(a[2].center, 3 * kInch, kInch, -0.25 * kInch);
}

TEST(InterpPrograms, FanucSubprogramSteps) {
  auto r = run_file("fanuc_grooves.ngc");
  ASSERT_TRUE(r->ok) << (r->diags.all().empty() ? "" : r->diags.all()[0].message);
  // The end of each groove: at depth, 20 mm along Y.
  std::vector<double> groove_x;
  for (const Feed& m : r->all<Feed>()) {
    if (m.to.z < -1.9 && m.to.y > 19.9) groove_x.push_back(m.to.x);
    if (m.to.z < -1.9) {
      EXPECT_NEAR(m.to.z, -2.0, kTol);
    }
  }
  ASSERT_EQ(groove_x.size(), 5u);
  for (std::size_t i = 0; i < 5; ++i) {
    EXPECT_NEAR(groove_x[i], 10.0 + 8.0 * static_cast<double>(i), kTol);
  }
}

TEST(InterpPrograms, BadArcIsReportedAtItsBlock) {
  auto r = run_file("bad_arc.ngc");
  EXPECT_FALSE(r->ok);
  const auto errors = r->of_severity(core::Severity::Error);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(core::code_name(errors[0].code), core::code_name(Code::ArcRadiusTooSmall));
  EXPECT_EQ(errors[0].loc.line, 7u);
}

// A part drawing leaves out what a canned cycle expands: its ops say so.
TEST(Origin, CycleMovesAreMarkedAndTheirBlockIsNot) {
  auto r = run("G0 X0 Y0 Z5\nG81 X10 Y0 Z-3 R1 F100\nG80\nG1 X20 F100\nM2\n");
  ASSERT_TRUE(r->ok);
  int cycle = 0;
  for (const canon::Op& op : r->ops()) {
    if (!canon::is_motion(op.kind)) continue;
    const bool in_cycle = op.src.line == 2;
    EXPECT_EQ(op.origin == canon::Origin::Cycle, in_cycle) << canon::op_name(op.kind);
    cycle += in_cycle ? 1 : 0;
  }
  EXPECT_GE(cycle, 3);
}

// With compensation ignored the moves are the programmed contour.
TEST(Origin, IgnoredCutterCompGivesTheProgrammedPath) {
  InterpOptions opts;
  ToolEntry t;
  t.number = 1;
  t.diameter = 10.0;
  opts.tools.set(t);
  opts.ignore_cutter_comp = true;
  auto r = run("T1 M6\nG0 X0 Y0\nG41 G1 X10 Y0 F100\nX10 Y10\nG40 X0 Y10\nM2\n", opts);
  ASSERT_TRUE(r->ok);
  const auto ends = r->ends();
  ASSERT_GE(ends.size(), 4U);
  EXPECT_EQ(show(ends[ends.size() - 3]), show({10, 0, 0}));
  EXPECT_EQ(show(ends[ends.size() - 2]), show({10, 10, 0}));
  EXPECT_EQ(show(ends.back()), show({0, 10, 0}));
}

}  // namespace
}  // namespace usina::gcode
