// usina --dialect auto: the file's name is a hint, the note says which clues
// decided (docs/dialects.md, "Guessing the dialect").
#include <string>

#include <gtest/gtest.h>

#include "support/usina_process.hpp"

namespace usina::test {
namespace {

// A Grbl job as Fusion 360's Grbl post writes it: a tool named, never
// changed; no '$' line.
constexpr const char* kFusionGrbl =
    "(1070_wall)\n(T1  D=2.7 CR=0 - ZMIN=-12.55 - flat end mill)\nG90 G94\nG17\nG21\n"
    "T1\nS5000 M3\nG54\nG0 X-1.347 Y33.181\nZ10\nG1 Z5 F1000\nX2 Y30\n";

TEST(DialectGuessCli, TheFileNameIsAHint) {
  const TempDir dir;
  const std::string plain = "G0 X1\nG1 X2 F100\nM30\n";
  const test::Run gcode = usina("check --dialect auto " + quote(dir.write("job.gcode", plain)));
  EXPECT_EQ(gcode.status, 0) << gcode.err;
  EXPECT_TRUE(contains(gcode.err, "auto chose grbl (grbl 1: the extension '.gcode'")) << gcode.err;
  const test::Run ngc = usina("check --dialect auto " + quote(dir.write("job.ngc", plain)));
  EXPECT_TRUE(contains(ngc.err, "auto chose rs274ngc (rs274ngc 4: the extension '.ngc'"))
      << ngc.err;
  const test::Run piped = usina("check --dialect auto -", plain);
  EXPECT_TRUE(contains(piped.err, "auto chose rs274ngc (no dialect's mark or clue")) << piped.err;
}

TEST(DialectGuessCli, AGrblPostWithoutDollarLinesIsGrbl) {
  const TempDir dir;
  const test::Run r = usina("check --dialect auto " + quote(dir.write("wall.nc", kFusionGrbl)));
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(contains(r.err, "auto chose grbl")) << r.err;
  EXPECT_TRUE(contains(r.err, "a T word and no M6")) << r.err;
  EXPECT_TRUE(contains(r.err, "no M2, M30 or '%' at its end")) << r.err;
  EXPECT_TRUE(contains(r.err, "[N_DIALECT_GUESS]")) << r.err;
}

}  // namespace
}  // namespace usina::test
