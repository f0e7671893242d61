// No back end ever receives NaN, an infinity or a number out of canon's
// range (issue 11): random programs of extreme values (huge exponents,
// products of 10**308, tiny divisors, hundreds of digits, offsets, scale
// factors, increments, arcs of huge radius) run through every dialect into
// a sink that checks every number of every op. The programs are made here
// from a fixed seed, so a failure repeats; the program is printed with it.
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "canon/limits.hpp"
#include "core/source.hpp"
#include "gcode/dialect.hpp"

namespace usina::gcode {
namespace {

// Fails the test on an op with a number that is not finite (checked field
// by field, independently of canon/limits.cpp) or out of canon's range.
class FiniteSink final : public canon::Sink {
 public:
  std::string program;  // for the failure message
  int ops = 0;

  void on(const canon::Op& op) override {
    ++ops;
    std::visit([this](const auto& k) { check(k); }, op.kind);
    const auto in_range = canon::check_range(op.kind);
    EXPECT_TRUE(in_range) << (in_range ? "" : in_range.error()) << "\n" << program;
  }

 private:
  void num(double v, const char* what) {
    EXPECT_TRUE(std::isfinite(v)) << what << " = " << v << "\n" << program;
  }

  void point(const core::Vec3& p, const char* what) {
    num(p.x, what);
    num(p.y, what);
    num(p.z, what);
  }

  void abc(const canon::Abc& a) {
    for (const double v : a)
      num(v, "abc");
  }

  void feed(const std::optional<double>& f, const canon::ProgrammedFeed& p) {
    if (f) num(*f, "f");
    num(p.value, "programmed feed");
  }

  void check(const canon::Traverse& t) {
    point(t.to, "traverse");
    abc(t.abc);
  }

  void check(const canon::Feed& f) {
    point(f.to, "feed");
    abc(f.abc);
    feed(f.f, f.programmed);
  }

  void check(const canon::Arc& a) {
    point(a.to, "arc end");
    point(a.center, "arc centre");
    point(a.normal, "arc normal");
    abc(a.abc);
    feed(a.f, a.programmed);
  }

  void check(const canon::Spline& s) {
    point(s.to, "spline");
    for (const core::Vec3& p : s.points)
      point(p, "spline point");
    feed(s.f, s.programmed);
  }

  void check(const canon::Probe& p) {
    point(p.to, "probe");
    abc(p.abc);
  }

  void check(const canon::Dwell& d) { num(d.s, "dwell"); }

  void check(const canon::PathMode& m) {
    num(m.tolerance, "G64 P");
    num(m.naive_cam, "G64 Q");
  }

  void check(const canon::ToolChange& t) {
    if (t.diameter) num(*t.diameter, "tool diameter");
  }

  void check(const canon::Spindle& s) { num(s.rpm, "rpm"); }

  void check(const canon::Hole& h) {
    point(h.at, "hole");
    num(h.diameter, "hole diameter");
    num(h.depth, "hole depth");
  }

  void check(const canon::Pocket& p) {
    num(p.outline.start.x, "pocket");
    num(p.outline.start.y, "pocket");
    for (const canon::OutlineSegment& s : p.outline.segs) {
      num(s.to.x, "pocket");
      num(s.to.y, "pocket");
    }
    num(p.depth, "pocket depth");
  }

  void check(const canon::Coolant&) {}

  void check(const canon::Comment&) {}

  void check(const canon::ProgramEnd&) {}

  void check(const canon::MachineCode&) {}
};

// What one dialect's programs are made of: block templates whose
// placeholders take ordinary values (@ a coordinate, ! a positive rate or
// count, ~ a scale factor) or, now and then, an extreme one.
struct Grammar {
  const char* dialect;
  std::vector<const char*> blocks;
  std::vector<std::string> extreme;
  const char* end;
};

std::string ordinary(char kind, std::mt19937_64& rng) {
  if (kind == '!') return fmt::format("{}", std::uniform_int_distribution<int>(1, 999)(rng));
  if (kind == '~') return fmt::format("{:.2f}", std::uniform_real_distribution<>(0.5, 2.0)(rng));
  return fmt::format("{:.3f}", std::uniform_real_distribution<>(-200.0, 200.0)(rng));
}

// A program that mostly runs (so that offsets, increments, scale factors
// and modes build up), with a few extreme values among its words.
std::string make_program(const Grammar& g, std::mt19937_64& rng) {
  std::uniform_int_distribution<std::size_t> pick_block(0, g.blocks.size() - 1);
  std::uniform_int_distribution<std::size_t> pick_extreme(0, g.extreme.size() - 1);
  std::bernoulli_distribution is_extreme(0.06);
  std::string text;
  const int n = std::uniform_int_distribution<int>(4, 24)(rng);
  for (int b = 0; b < n; ++b) {
    for (const char c : std::string_view(g.blocks[pick_block(rng)])) {
      if (c != '@' && c != '!' && c != '~') {
        text.push_back(c);
      } else {
        text += is_extreme(rng) ? g.extreme[pick_extreme(rng)] : ordinary(c, rng);
      }
    }
    text.push_back('\n');
  }
  return text + g.end;
}

// Runs `count` programs of `g`; returns how many ended without an error.
int run_programs(const Grammar& g, int count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const Dialect* d = find_dialect(g.dialect);
  EXPECT_NE(d, nullptr);
  int clean = 0;
  for (int i = 0; i < count; ++i) {
    core::SourceManager sources;
    core::DiagnosticList diags;
    FiniteSink sink;
    sink.program = make_program(g, rng);
    const std::uint32_t id = sources.add(core::SourceFile::from_string("x.nc", sink.program));
    const OptionValues values = default_options(*d);
    auto runner = d->make_runner(RunContext{sources, InterpOptions{}, values, sink, diags});
    clean += runner->run(id) ? 1 : 0;
    if (::testing::Test::HasFailure()) break;  // one program shown is enough
  }
  return clean;
}

// The extremes every dialect can write as plain numbers.
std::vector<std::string> plain_extremes() {
  return {"999999999",
          "1000000001",
          "-999999999.",
          "99999999999",
          "0.0000001",
          "0.000000001",
          "1e400",
          "1e-400",
          "1e3",
          std::string(400, '9'),
          "0." + std::string(330, '0') + "1"};
}

TEST(ExtremeValues, Rs274ngc) {
  Grammar g{"rs274ngc",
            {"G0 X@ Y@ Z@",
             "G1 X@ Y@ F!",
             "G2 X@ Y@ R!0 F!",
             "G3 I@ J@ F!",
             "G2 I@ J@ Z@ P! F!",
             "G18 G2 X@ Z@ R!0 F!",
             "G17",
             "G91",
             "G90",
             "G20",
             "G21",
             "G92 X@ Y@",
             "G92.1",
             "G52 X@ Z@",
             "G10 L2 P1 X@ Y@ R@",
             "G10 L20 P2 Z@",
             "G55",
             "G54",
             "G43.1 Z@",
             "G49",
             "G4 P!",
             "S! M3",
             "M5",
             "G93 G1 X@ F!",
             "G94",
             "S! M3 G95 G1 Y@ F!",
             "G94",
             "G81 X@ Y@ R! Z-! F!",
             "G83 X@ R! Z-! Q! F!",
             "G80",
             "G91 G81 X@ R! Z-! L! F!",
             "G90",
             "#1=@",
             "G0 X#1",
             "G0 X[#1*#1]",
             "G1 X[@/!] F!",
             "G10 L1 P1 Z@ R!",
             "G43 H1",
             "G38.2 X@ F!",
             "G5.1 X@ Y@ I@ J@ F!",
             "G0 @@ ^@"},
            plain_extremes(),
            "M2\n"};
  for (const char* e : {"[10**308]", "[10**308*10]", "[-10**200]", "[1/[10**-300]]", "[10**-320]",
                        "[2**1023*2]", "[EXP[700]]", "[SQRT[10**300]]", "[10**9]", "[-10**9]",
                        "[1/0.0000000001]", "[10**308-10**308]"})
    g.extreme.emplace_back(e);
  EXPECT_GT(run_programs(g, 1500, 11), 100);  // most programs run to their end
}

TEST(ExtremeValues, Fanuc) {
  Grammar g{"fanuc",
            {"G0 X@ Y@ Z@", "G1 X@ Y@ F!",  "G2 X@ Y@ R!0. F!",
             "G3 I@ J@ F!", "G91",          "G90",
             "G92 X@ Y@",   "G52 X@",       "G10 L2 P1 X@ Y@",
             "G04 P!",      "S! M03",       "G51 X0 Y0 P!000",
             "G50",         "G68 X0 Y0 R@", "G69",
             "G51.1 X@",    "G50.1 X0",     "G81 X@ Y@ R! Z-! F!",
             "G80",         "#1=@",         "#2=#1*#1",
             "G0 X#1 Y#2",  "#3=EXP[@]",    "G1 X[@/!] F!",
             "G91 G0 X@",   "G90"},
            plain_extremes(),
            "M30\n"};
  for (const char* e : {"[99999999.*99999999.*99999999.]", "[1/0.000000001]", "EXP[1000]",
                        "[SQRT[99999999.]*99999999.]", "-1e400", "999999999."})
    g.extreme.emplace_back(e);
  EXPECT_GT(run_programs(g, 1500, 12), 100);
}

TEST(ExtremeValues, Romi) {
  Grammar g{"romi",
            {"G0 X@ Y@", "G1 X@ Y@ F!", "G2 X@ Y@ R!0 F!", "G91", "G90", "G72 K~", "G72 X~ Y~",
             "G73 C@ I@ J@", "G73 C0", "G31 X@", "G30", "G81 R! Z! F!", "G80", "S! M03",
             "G91 G0 X@", "G90"},
            plain_extremes(),
            "M30\n"};
  g.extreme.emplace_back("20");
  EXPECT_GT(run_programs(g, 1500, 13), 100);
}

TEST(ExtremeValues, Grbl) {
  Grammar g{"grbl",
            {"G0 X@ Y@ Z@", "G1 X@ Y@ F!", "G2 X@ Y@ R!0 F!", "G3 I@ J@ F!", "G91", "G90",
             "G92 X@ Y@", "G10 L2 P1 X@", "G10 L20 P1 Y@", "G4 P!", "S! M3", "G93 G1 X@ F!", "G94",
             "G43.1 Z@", "G20", "G21", "G91 G0 X@", "G90"},
            plain_extremes(),
            "M2\n"};
  EXPECT_GT(run_programs(g, 1500, 14), 100);
}

}  // namespace
}  // namespace usina::gcode
