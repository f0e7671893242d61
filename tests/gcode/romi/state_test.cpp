// The romi dialect's modal state is a value: a block works on a copy that
// replaces the state only when the block succeeded, so a failed block
// changes no mode (DESIGN.md, "Inside the gcode front end"; romi/state.hpp).
// The ops a block sent before its error stay sent.
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "canon/toolpath.hpp"
#include "core/source.hpp"
#include "gcode/romi/engine.hpp"

namespace usina::gcode::romi {
namespace {

using core::Code;

struct StateRun {
  core::SourceManager sources;
  core::DiagnosticList diags;
  canon::Toolpath path;
  std::unique_ptr<Engine> engine;
  bool ok = false;

  const Modal& state() const { return engine->state(); }

  Code first_error() const {
    for (const core::Diagnostic& d : diags.all()) {
      if (d.severity == core::Severity::Error) return d.code;
    }
    return Code::Message;
  }
};

std::unique_ptr<StateRun> run(const std::string& text, InterpOptions opts = {}) {
  auto r = std::make_unique<StateRun>();
  const std::uint32_t id = r->sources.add(core::SourceFile::from_string("test.nc", text));
  const Dialect& d = *find_dialect("romi");
  OptionValues values = default_options(d);
  r->engine = std::make_unique<Engine>(
      d, code_table(),
      RunContext{r->sources, std::move(opts), std::move(values), r->path, r->diags});
  r->ok = r->engine->run(id);
  return r;
}

TEST(RomiState, ASuccessfulBlockCommitsItsModes) {
  auto r = run("G91 G72 K2 G31 X5#T4 O2 F120 S900 G70#M02#");
  ASSERT_TRUE(r->ok);
  const Modal& m = r->state();
  EXPECT_TRUE(m.machine.incremental);
  EXPECT_EQ(m.tf.scale_x, 2.0);
  EXPECT_TRUE(m.tf.mirror_x);
  EXPECT_EQ(m.tf.mirror_at.x, 5.0);
  EXPECT_EQ(m.machine.selected_tool, 4);
  EXPECT_EQ(m.offset_register, 2);
  EXPECT_EQ(m.machine.feed, 120.0);
  EXPECT_EQ(m.machine.speed, 900.0);
  EXPECT_EQ(m.machine.units, core::LengthUnit::Inch);
}

TEST(RomiState, AnErrorInTheBlockOfG91LeavesTheDistanceModeAsItWas) {
  // G91 (group 11) runs before G72 (group 21), whose factor is refused.
  auto r = run("G91 G72 K30#M02#");
  EXPECT_FALSE(r->ok);
  EXPECT_EQ(r->first_error(), Code::ScaleOutOfRange);
  EXPECT_FALSE(r->state().machine.incremental);
  EXPECT_EQ(r->state().tf.scale_x, 1.0);
}

TEST(RomiState, AnErrorAfterAScaleLeavesTheScaleAsItWas) {
  // G72 runs (it takes K, X and Y), then the move has no feed rate.
  auto r = run("G72 K2 G01 Z-5#M02#");
  EXPECT_EQ(r->first_error(), Code::NoFeedRate);
  EXPECT_EQ(r->state().tf.scale_x, 1.0);
  EXPECT_EQ(r->state().tf.scale_y, 1.0);
  EXPECT_EQ(r->state().motion(), 0);
}

TEST(RomiState, TheValuesOfAFailedBlockAreNotKept) {
  auto r = run("T5 O3 F200 S1000 G70 G72 K50#M02#");
  EXPECT_EQ(r->first_error(), Code::ScaleOutOfRange);
  const Modal& m = r->state();
  EXPECT_EQ(m.machine.selected_tool, -1);
  EXPECT_EQ(m.offset_register, 0);
  EXPECT_EQ(m.machine.feed, 0.0);
  EXPECT_EQ(m.machine.speed, 0.0);
  EXPECT_EQ(m.machine.units, core::LengthUnit::Mm);
}

TEST(RomiState, EarlierBlocksStayCommittedWhenALaterBlockFails) {
  auto r = run("G91#G72 K2#G31 X1 G72 K40#M02#");
  EXPECT_EQ(r->first_error(), Code::ScaleOutOfRange);
  EXPECT_TRUE(r->state().machine.incremental);
  EXPECT_EQ(r->state().tf.scale_x, 2.0);
  EXPECT_FALSE(r->state().tf.mirror_x);
}

TEST(RomiState, AFailedBlockSentItsMoveButKeepsTheProgrammedPoint) {
  // The unused K is found after the move went out.
  auto r = run("G01 F100 X10#G01 Y20 K5#M02#");
  EXPECT_EQ(r->first_error(), Code::UnusedWord);
  const auto& ops = r->path.ops();
  ASSERT_FALSE(ops.empty());
  const auto* last = std::get_if<canon::Feed>(&ops.back().kind);
  ASSERT_NE(last, nullptr);
  EXPECT_EQ(last->to.y, 20.0);  // sent, as a control's move is made
  EXPECT_EQ(r->state().pos.x, 10.0);
  EXPECT_EQ(r->state().pos.y, 0.0);
  ASSERT_TRUE(r->state().direction.degrees().has_value());
  EXPECT_EQ(*r->state().direction.degrees(), 0.0);  // along +X, the last committed move
}

TEST(RomiState, AFailedCompensationBlockLeavesCompensationOff) {
  // G41 starts compensation, then the G01 has no feed rate.
  auto r = run("T1 M06 ;fresa d10#G41 G01 X10 Y10#M02#");
  EXPECT_EQ(r->first_error(), Code::NoFeedRate);
  EXPECT_FALSE(r->state().comp_on);
  EXPECT_EQ(r->state().machine.tool, 1);  // the tool change's block succeeded
}

TEST(RomiState, AFailedToolChangeBlockKeepsTheToolInTheSpindle) {
  // M06 (group 1) runs first; the rotation after it lacks C.
  auto r = run("T3 M06 G73 ;fresa d8#M02#");
  EXPECT_EQ(r->first_error(), Code::MissingWord);
  EXPECT_EQ(r->state().machine.tool, 0);
  EXPECT_EQ(r->state().tool_diameter, 0.0);
  EXPECT_EQ(r->state().machine.selected_tool, -1);
}

TEST(RomiState, AJumpErrorFailsTheWholeBlock) {
  auto r = run("G91 (GOTO N99)#M02#");
  EXPECT_EQ(r->first_error(), Code::UnknownBlockNumber);
  EXPECT_FALSE(r->state().machine.incremental);
}

TEST(RomiState, ABlendArcOfAFailedBlockIsNotPending) {
  // G02 R5 holds a blend arc; the unused Q fails the block.
  auto r = run("G01 F100 X10#G02 R5 Q1#G01 X40 Y40#M02#");
  EXPECT_EQ(r->first_error(), Code::UnusedWord);
  EXPECT_FALSE(r->state().blend.has_value());
  EXPECT_EQ(r->state().motion(), 1);
}

TEST(RomiState, TheStartCodesAreTheStateBeforeTheFirstBlock) {
  auto r = run("G72 K99#");
  EXPECT_FALSE(r->ok);
  const Modal& m = r->state();
  EXPECT_EQ(m.motion(), 0);
  EXPECT_FALSE(m.machine.incremental);
  EXPECT_EQ(m.machine.retract, RetractMode::RPlane);
  EXPECT_FALSE(m.drill.active);
  EXPECT_FALSE(m.comp_on);
  EXPECT_EQ(m.machine.units, core::LengthUnit::Mm);
}

}  // namespace
}  // namespace usina::gcode::romi
