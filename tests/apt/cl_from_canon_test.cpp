// Issue 15, CL data of a G-code program: the canon stream written as CL
// records (CanonToCl), read back by ClToCanon, through binary CLDATA and
// ISO 4343 text, gives the same moves (positions within 1e-6, arc centres
// and directions, feeds), tools, spindle and coolant; a plain drilling is
// CYCLE/DRILL and comes back as its moves and its hole.
#include "apt/cl_from_canon.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "apt/canon_out.hpp"
#include "apt/cl_text.hpp"
#include "apt/cldata.hpp"
#include "apt/iso4343.hpp"

namespace usina::apt::test {
namespace {

using canon::Op;
using canon::Origin;
using canon::Vec3;

class Ops final : public canon::Sink {
 public:
  void on(const Op& op) override { ops.push_back(op); }

  std::vector<Op> ops;
};

std::vector<Op> back(const std::vector<ClRecord>& records) {
  Ops s;
  to_canon(records, 1.0, s);
  return s.ops;
}

Op op(canon::OpKind k, unsigned line = 1, Origin o = Origin::Program) {
  return Op{std::move(k), core::SourceLoc{0, line, 1}, o};
}

void expect_near(const Vec3& a, const Vec3& b, const char* what) {
  EXPECT_NEAR(a.x, b.x, 1e-6) << what;
  EXPECT_NEAR(a.y, b.y, 1e-6) << what;
  EXPECT_NEAR(a.z, b.z, 1e-6) << what;
}

// Same kinds in the same order, same positions, arcs with the same centre
// and sense, feeds with the same rate.
void expect_same(const std::vector<Op>& want, const std::vector<Op>& got) {
  ASSERT_EQ(want.size(), got.size());
  for (std::size_t i = 0; i < want.size(); ++i) {
    ASSERT_EQ(want[i].kind.index(), got[i].kind.index()) << "op " << i;
    std::visit(
        [&](const auto& w) {
          using K = std::decay_t<decltype(w)>;
          const K& g = std::get<K>(got[i].kind);
          if constexpr (std::is_same_v<K, canon::Traverse>) expect_near(w.to, g.to, "traverse");
          if constexpr (std::is_same_v<K, canon::Feed>) {
            expect_near(w.to, g.to, "feed");
            EXPECT_EQ(w.f, g.f) << "op " << i;
          }
          if constexpr (std::is_same_v<K, canon::Arc>) {
            expect_near(w.to, g.to, "arc end");
            expect_near(w.center, g.center, "arc centre");
            const double s = w.turn > 0 ? 1.0 : -1.0;
            expect_near({w.normal.x * s, w.normal.y * s, w.normal.z * s},
                        {g.normal.x * g.turn, g.normal.y * g.turn, g.normal.z * g.turn}, "sense");
            EXPECT_EQ(w.f, g.f) << "op " << i;
          }
          if constexpr (std::is_same_v<K, canon::ToolChange>) {
            EXPECT_EQ(w.tool, g.tool);
            EXPECT_EQ(w.diameter, g.diameter);
          }
          if constexpr (std::is_same_v<K, canon::Spindle>) {
            EXPECT_EQ(w.rpm, g.rpm);
            EXPECT_EQ(w.dir, g.dir);
          }
          if constexpr (std::is_same_v<K, canon::Coolant>) {
            EXPECT_EQ(w.mist, g.mist);
            EXPECT_EQ(w.flood, g.flood);
          }
          if constexpr (std::is_same_v<K, canon::Hole>) {
            expect_near(w.at, g.at, "hole");
            EXPECT_NEAR(w.depth, g.depth, 1e-9);
          }
          if constexpr (std::is_same_v<K, canon::Dwell>) {
            EXPECT_EQ(w.s, g.s);
          }
          if constexpr (std::is_same_v<K, canon::Comment>) {
            EXPECT_EQ(w.text, g.text);
          }
        },
        want[i].kind);
  }
}

// Through all three forms: the records themselves, CLDATA bytes, ISO 4343 text.
void expect_round_trip(const std::vector<Op>& ops, const std::vector<Op>& want) {
  const std::vector<ClRecord> records = canon_to_cl(ops);
  expect_same(want, back(records));
  core::DiagnosticList diags;
  expect_same(want, back(read_cldata(write_cldata(records), 0, diags)));
  expect_same(want, back(read_cl_text(write_iso4343(records, "MM"), 0, ClDialect::AptCl, diags)));
  EXPECT_TRUE(diags.all().empty());
}

TEST(CanonToCl, StraightMovesFeedsToolsSpindleCoolant) {
  const std::vector<Op> ops{
      op(canon::ToolChange{3, 6.0}),
      op(canon::Spindle{1200, canon::SpindleDir::Cw}),
      op(canon::Coolant{false, true}),
      op(canon::Traverse{{1, 2, 5}, {}}, 2),
      op(canon::Feed{{1, 2, -1}, 100.0, {}, {}}, 3),
      op(canon::Feed{{11.123456789, 2, -1}, 250.0, {}, {}}, 4),
      op(canon::Feed{{11.123456789, 7, -1}, 250.0, {}, {}}, 5),
      op(canon::Traverse{{0, 0, 5}, {}}, 6),
      op(canon::Dwell{1.5}, 7),
      op(canon::Comment{"ROUGHING PASS, THEN FINISH"}, 8),
      op(canon::Spindle{800, canon::SpindleDir::Ccw}, 9),
      op(canon::Coolant{true, false}, 10),
      op(canon::Coolant{false, false}, 11),
      op(canon::Spindle{800, canon::SpindleDir::Off}, 12),
      op(canon::ProgramEnd{}, 13),
  };
  expect_round_trip(ops, ops);
}

TEST(CanonToCl, FeedIsWrittenOnlyWhenItChanges) {
  const std::vector<ClRecord> r = canon_to_cl({
      op(canon::Feed{{1, 0, 0}, 100.0, {}, {}}),
      op(canon::Feed{{2, 0, 0}, 100.0, {}, {}}),
      op(canon::Feed{{3, 0, 0}, 200.0, {}, {}}),
  });
  int fedrat = 0;
  for (const ClRecord& x : r)
    fedrat += x.cls == cls::kPost && x.sub == 1009;
  EXPECT_EQ(fedrat, 2);
  EXPECT_EQ(r.back().cls, cls::kFini);
}

// A quarter counter-clockwise in XY, a half clockwise, a helix, an arc in
// XZ (G18), a whole circle (to where it began).
TEST(CanonToCl, ArcsKeepCentreAndSense) {
  const std::vector<Op> ops{
      op(canon::Traverse{{10, 0, 0}, {}}),
      op(canon::Arc{{0, 10, 0}, {0, 0, 0}, {0, 0, 1}, 1, 300.0, {}, {}}, 2),
      op(canon::Arc{{0, -10, 0}, {0, 0, 0}, {0, 0, 1}, -1, 300.0, {}, {}}, 3),
      op(canon::Arc{{10, 0, -2}, {0, 0, 0}, {0, 0, 1}, 1, 150.0, {}, {}}, 4),
      op(canon::Arc{{10, 0, -2}, {5, 0, -2}, {0, 0, 1}, -1, 150.0, {}, {}}, 5),
      op(canon::Arc{{20, 0, -12}, {15, 0, -7}, {0, -1, 0}, 1, 150.0, {}, {}}, 6),
  };
  expect_round_trip(ops, ops);
  // IBM's form: the circle's record (centre, axis counter-clockwise, radius), then the GOTO.
  const std::vector<ClRecord> r = canon_to_cl(ops);
  std::vector<const ClRecord*> circles;
  for (const ClRecord& x : r)
    if (x.cls == cls::kSurface) circles.push_back(&x);
  ASSERT_EQ(circles.size(), 5u);
  EXPECT_EQ(circles[1]->words[10].real, -1.0);  // the clockwise half: axis -k
  EXPECT_EQ(circles[1]->words[11].real, 10.0);  // radius
  EXPECT_EQ(circles[3]->words[11].real, 5.0);
}

// Two and a quarter turns of a helix: a circle a turn, then the rest, each
// rising its share of the 9 mm.
TEST(CanonToCl, AnArcOfSeveralTurnsIsACircleATurn) {
  const std::vector<Op> ops{
      op(canon::Traverse{{10, 0, 0}, {}}),
      op(canon::Arc{{0, 10, -9}, {0, 0, 0}, {0, 0, 1}, 3, 100.0, {}, {}}, 2),
  };
  const std::vector<Op> got = back(canon_to_cl(ops));
  ASSERT_EQ(got.size(), 4u);
  const double per_turn = 9.0 / 2.25;
  expect_near(std::get<canon::Arc>(got[1].kind).to, {10, 0, -per_turn}, "turn 1");
  expect_near(std::get<canon::Arc>(got[2].kind).to, {10, 0, -2 * per_turn}, "turn 2");
  expect_near(std::get<canon::Arc>(got[3].kind).to, {0, 10, -9}, "the rest");
  for (std::size_t i = 1; i < 4; ++i)
    EXPECT_EQ(std::get<canon::Arc>(got[i].kind).turn, 1);
}

// G81 as the interpreter gives it: over the hole, down to R, the hole, fed
// to the bottom, out to the clear level (G98: above R).
std::vector<Op> g81(double x, double y, unsigned line) {
  return {op(canon::Traverse{{x, y, 10}, {}}, line, Origin::Cycle),
          op(canon::Traverse{{x, y, 2}, {}}, line, Origin::Cycle),
          op(canon::Hole{{x, y, 2}, 5.0, 7.0}, line, Origin::Cycle),
          op(canon::Feed{{x, y, -5}, 120.0, {}, {}}, line, Origin::Cycle),
          op(canon::Traverse{{x, y, 10}, {}}, line, Origin::Cycle)};
}

TEST(CanonToCl, PlainDrillingIsCycleDrill) {
  std::vector<Op> ops{op(canon::ToolChange{1, 5.0})};
  for (const Op& o : g81(10, 10, 2))
    ops.push_back(o);
  for (const Op& o : g81(30, 10, 3))
    ops.push_back(o);
  ops.push_back(op(canon::Feed{{0, 0, 10}, 500.0, {}, {}}, 4));
  // Back: the hole after the moves that drill it (ClToCanon's order).
  std::vector<Op> want;
  for (const std::size_t i : {0, 1, 2, 4, 5, 3, 6, 7, 9, 10, 8, 11})
    want.push_back(ops[i]);
  expect_round_trip(ops, want);
  const std::vector<ClRecord> r = canon_to_cl(ops);
  int cycles = 0, offs = 0;
  for (const ClRecord& x : r) {
    if (x.cls != cls::kPost || x.sub != 1054) continue;
    if (x.words.size() == 6) {
      ++cycles;
      EXPECT_EQ(x.words[0].code, 163);    // DRILL
      EXPECT_EQ(x.words[1].real, 7.0);    // depth
      EXPECT_EQ(x.words[3].real, 120.0);  // feed
      EXPECT_EQ(x.words[4].real, 0.0);    // clearance: the GOTO is R
      EXPECT_EQ(x.words[5].real, 8.0);    // out to 8 above R (G98)
    } else {
      ++offs;
    }
  }
  EXPECT_EQ(cycles, 1);  // the second hole drills in the open cycle
  EXPECT_EQ(offs, 1);    // closed before the feed
}

// romi's G79 drilling: the hole's top is the surface, drilled from a
// clearance above it and left back to it: CYCLE/DRILL,40,MMPM,150,2.
TEST(CanonToCl, DrillingFromAClearanceAboveTheTop) {
  const std::vector<Op> ops{
      op(canon::Traverse{{500, 280, 0}, {}}),
      op(canon::Traverse{{500, 280, 2}, {}}, 2, Origin::Cycle),
      op(canon::Hole{{500, 280, 0}, 20.0, 40.0}, 2, Origin::Cycle),
      op(canon::Feed{{500, 280, -40}, 150.0, {}, {}}, 2, Origin::Cycle),
      op(canon::Traverse{{500, 280, 2}, {}}, 2, Origin::Cycle),
  };
  expect_round_trip(ops, {ops[0], ops[1], ops[3], ops[4], ops[2]});
  const std::vector<ClRecord> r = canon_to_cl(ops);
  const auto cycle = std::find_if(
      r.begin(), r.end(), [](const ClRecord& x) { return x.cls == cls::kPost && x.sub == 1054; });
  ASSERT_NE(cycle, r.end());
  ASSERT_EQ(cycle->words.size(), 5u);  // no retract: it leaves to the clearance
  EXPECT_EQ(cycle->words[1].real, 40.0);
  EXPECT_EQ(cycle->words[4].real, 2.0);
}

// A pecked or dwelt hole is its moves: the hole is lost, no move is.
TEST(CanonToCl, OtherHolesAreTheirMoves) {
  const std::vector<Op> ops{
      op(canon::Traverse{{5, 5, 2}, {}}, 1, Origin::Cycle),
      op(canon::Hole{{5, 5, 2}, 5.0, 7.0}, 1, Origin::Cycle),
      op(canon::Feed{{5, 5, -5}, 120.0, {}, {}}, 1, Origin::Cycle),
      op(canon::Dwell{0.5}, 1, Origin::Cycle),
      op(canon::Traverse{{5, 5, 2}, {}}, 1, Origin::Cycle),
      op(canon::Hole{{5, 5, 2}, 5.0, 7.0}, 2, Origin::Cycle),  // the file ends holding it
  };
  std::vector<Op> want{ops[0], ops[2], ops[3], ops[4]};
  expect_round_trip(ops, want);
}

// G93: the move's rate in mm/min takes it the same time; G95 per revolution.
TEST(CanonToCl, InverseTimeAndPerRevolutionFeeds) {
  using Mode = canon::ProgrammedFeed::Mode;
  const std::vector<Op> ops{
      op(canon::Traverse{{0, 0, 0}, {}}),
      op(canon::Feed{{30, 40, 0}, {}, {}, {Mode::InverseTime, 2.0}}, 2),  // 50 mm in 0.5 min
      op(canon::Feed{{30, 40, -1}, {}, {}, {Mode::PerRevolution, 0.1}}, 3),
  };
  const std::vector<Op> got = back(canon_to_cl(ops));
  ASSERT_EQ(got.size(), 3u);
  EXPECT_EQ(std::get<canon::Feed>(got[1].kind).f, 100.0);
  const auto& rev = std::get<canon::Feed>(got[2].kind);
  EXPECT_EQ(rev.programmed.mode, Mode::PerRevolution);
  EXPECT_EQ(rev.programmed.value, 0.1);
}

// A long stream flushed in parts gives the bytes of the whole, each part
// numbered on from the last; a hole's approach is never split from it.
TEST(CanonToCl, FlushedInPartsIsTheWhole) {
  std::vector<Op> ops;
  for (int i = 0; i < 3000; ++i) {
    ops.push_back(op(canon::Feed{{i * 1.0, 0, 0}, 100.0 + i % 3, {}, {}}));
    for (const Op& o : g81(i * 1.0, 5, 2))
      if (i % 100 == 0) ops.push_back(o);
  }
  std::string parts, print;
  std::size_t n = 0, flushes = 0;
  CanonToCl cl([&](std::vector<ClRecord>&& r) {
    parts += write_cldata(r, static_cast<std::uint32_t>(n + 1));
    print += record_print(r, n + 1);
    n += r.size();
    ++flushes;
  });
  for (const Op& o : ops)
    cl.on(o);
  cl.finish();
  const std::vector<ClRecord> whole = canon_to_cl(ops);
  EXPECT_GT(flushes, 2u);
  EXPECT_TRUE(cl.records().empty());
  EXPECT_EQ(n, whole.size());
  EXPECT_EQ(parts, write_cldata(whole));
  EXPECT_EQ(print, record_print(whole));
}

// Random streams of traverses, feeds, arcs (either way, helical, in XY) and
// plain drillings come back move for move (a fixed seed: the same streams
// every run).
TEST(CanonToCl, RandomStreamsComeBack) {
  std::mt19937 rng(15);
  std::uniform_real_distribution<double> u(-50.0, 50.0);
  for (int round = 0; round < 200; ++round) {
    std::vector<Op> ops{op(canon::Traverse{{u(rng), u(rng), 5}, {}})}, want = ops;
    Vec3 at = std::get<canon::Traverse>(ops[0].kind).to;
    for (unsigned line = 2; line < 40; ++line) {
      const int kind = static_cast<int>(rng() % 4);
      if (kind == 0) {
        at = {u(rng), u(rng), u(rng) / 10};
        ops.push_back(op(canon::Traverse{at, {}}, line));
        want.push_back(ops.back());
      } else if (kind == 1) {
        at = {u(rng), u(rng), u(rng) / 10};
        ops.push_back(op(canon::Feed{at, 100.0 + static_cast<double>(rng() % 3), {}, {}}, line));
        want.push_back(ops.back());
      } else if (kind == 2) {
        const Vec3 c{at.x + u(rng) / 5, at.y + u(rng) / 5, at.z};
        const double r = std::hypot(at.x - c.x, at.y - c.y), a = u(rng);
        at = {c.x + r * std::cos(a), c.y + r * std::sin(a), at.z + u(rng) / 25};
        ops.push_back(op(canon::Arc{at, c, {0, 0, 1}, rng() % 2 ? 1 : -1, 300.0, {}, {}}, line));
        want.push_back(ops.back());
      } else {
        const std::vector<Op> h = g81(u(rng), u(rng), line);
        ops.insert(ops.end(), h.begin(), h.end());
        for (const std::size_t i : {0, 1, 3, 4, 2})
          want.push_back(h[i]);
        at = std::get<canon::Traverse>(h[4].kind).to;
      }
    }
    SCOPED_TRACE(round);
    expect_round_trip(ops, want);
  }
}

TEST(CanonToCl, MachineCodesAndFinishOnce) {
  CanonToCl cl;
  cl.on(op(canon::MachineCode{'M', 0, {}, {}}));
  cl.on(op(canon::MachineCode{'M', 59, 2.0, {}}));
  cl.finish();
  cl.finish();
  cl.on(op(canon::Feed{{1, 0, 0}, 100.0, {}, {}}));
  const std::vector<Op> got = back(cl.records());
  ASSERT_EQ(got.size(), 2u);
  EXPECT_EQ(std::get<canon::MachineCode>(got[0].kind).code, 0);
  EXPECT_EQ(std::get<canon::Comment>(got[1].kind).text, "M59 P2");
  EXPECT_EQ(cl.records().back().cls, cls::kFini);
  EXPECT_EQ(cl.records().size(), 5u);  // 1000, STOP, 1000, INSERT, FINI
}

}  // namespace
}  // namespace usina::apt::test
