// usina gen from-dxf, pocket, profile, drill and engrave as a user runs them:
// exit status, what the post writes, the diagnostics, and every program read
// back by usina's own interpreter (`usina check`).
#include <unistd.h>  // unlink

#include <string>

#include <gtest/gtest.h>

#include "support/usina_process.hpp"

namespace {

using usina::test::contains;
using usina::test::count;
using usina::test::usina;
using Result = usina::test::Run;

const std::string kDxf = std::string(USINA_TEST_DIR) + "/programs/dxf/";

class GenCam : public ::testing::Test {
 protected:
  void SetUp() override { ASSERT_TRUE(contains(usina("gen --help").out, "engrave")); }

  // Generates with `args`, checks success, and reads the program back
  // (usina reads the rs274ngc dialect only: a romi program is not read back).
  std::string generate(const std::string& args, const std::string& ext = "ngc") {
    const std::string file = dir_.path("out." + ext);
    const Result r = usina("gen " + args + " -o '" + file + "'");
    EXPECT_EQ(r.status, 0) << r.err;
    const std::string program = usina::test::slurp(file);
    if (!contains(args, "--post romi")) {
      const Result check = usina("check '" + file + "'");
      EXPECT_EQ(check.status, 0) << args << "\n" << check.err;
    }
    ::unlink(file.c_str());
    return program;
  }

  // Runs `args` expecting bad input: status 2, `code` on stderr, no program.
  void fails(const std::string& args, const std::string& code) {
    const std::string file = dir_.path("fail.ngc");
    ::unlink(file.c_str());
    const Result r = usina("gen " + args + " -o '" + file + "'");
    EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
    EXPECT_TRUE(contains(r.err, code)) << args << "\n" << r.err;
    EXPECT_FALSE(usina::test::exists(file)) << "a failed run wrote " << file;
  }

 private:
  const usina::test::TempDir dir_;
};

TEST_F(GenCam, FromDxfKeepsArcsAsG3) {
  const std::string prog = generate("from-dxf --dxf '" + kDxf +
                                    "arcs_bulges.dxf' --layer SLOT --depth 1 --post rs274ngc");
  EXPECT_EQ(count(prog, "G3"), 2u) << prog;
}

TEST_F(GenCam, FromDxfErrors) {
  fails("from-dxf --dxf '" + kDxf + "no_such.dxf' --post rs274ngc", "E_DXF_UNREADABLE");
  fails("from-dxf --dxf '" + kDxf + "arcs_bulges.dxf' --layer NONE --post rs274ngc",
        "E_DXF_NO_ENTITIES");
  fails("from-dxf --dxf '" + kDxf +
            "arcs_bulges.dxf' --layer SLOT --side left --tool-diameter 12 "
            "--post rs274ngc",
        "E_GEN_TOOL_TOO_BIG");
}

TEST_F(GenCam, PocketOfEveryShape) {
  EXPECT_TRUE(contains(generate("pocket --rect 40,30 --corner-radius 4 --depth 3 --step-down 1.5 "
                                "--stepover 2.5 --post fanuc",
                                "nc"),
                       "G01 Z-3."));
  EXPECT_TRUE(contains(
      generate("pocket --circle 12 --center 5,5 --depth 1 --stepover 3 --post grbl", "gcode"),
      "Z-1"));
  EXPECT_FALSE(generate("pocket --dxf '" + kDxf +
                            "square_lines.dxf' --layer CUT --depth 2 "
                            "--stepover 2 --tool-diameter 3 --post romi",
                        "nc")
                   .empty());
}

TEST_F(GenCam, PocketErrors) {
  fails("pocket --circle 2 --depth 2 --stepover 2 --post rs274ngc", "E_GEN_TOOL_TOO_BIG");
  fails("pocket --circle 20 --depth 2 --stepover 7 --post rs274ngc", "E_GEN_BAD_VALUE");
  fails("pocket --dxf '" + kDxf +
            "arcs_bulges.dxf' --layer HOLES --depth 2 --stepover 2 "
            "--post rs274ngc",
        "E_GEN_OPEN_OUTLINE");
  fails("pocket --rect 10,10 --corner-radius 6 --depth 2 --stepover 2 --post rs274ngc",
        "E_GEN_BAD_VALUE");
}

TEST_F(GenCam, ProfileWithLeadsAndTabs) {
  const std::string prog =
      generate("profile --dxf '" + kDxf +
               "arcs_bulges.dxf' --layer SLOT --side outside "
               "--depth 4 --step-down 2 --lead-radius 3 --tabs 2 --tab-height 1 --post rs274ngc");
  EXPECT_TRUE(contains(prog, "G3")) << prog;   // the lead arcs
  EXPECT_TRUE(contains(prog, "Z-3")) << prog;  // the tabs' top: 1 mm above -4
}

TEST_F(GenCam, ProfileErrors) {
  fails("profile --dxf '" + kDxf +
            "arcs_bulges.dxf' --layer HOLES --side outside --depth 2 "
            "--post rs274ngc",
        "E_GEN_OPEN_OUTLINE");
  fails("profile --circle 10 --depth 2 --tabs 2 --tab-height 3 --post rs274ngc", "E_GEN_BAD_VALUE");
}

TEST_F(GenCam, DrillCyclesWhereTheControlHasThem) {
  const std::string prog =
      generate("drill --bolt-circle 0,0,30,6,15 --depth 10 --tool-diameter 8.5 --post fanuc", "nc");
  EXPECT_EQ(count(prog, "G81"), 1u) << prog;  // modal: one G81, six holes
  EXPECT_TRUE(
      contains(generate("drill --grid 0,0,3,2,10,10 --depth 5 --post rs274ngc --peck 2"), "G83"));
  const std::string grbl = generate("drill --at 1,2 --at 3,4 --depth 5 --post grbl", "gcode");
  EXPECT_FALSE(contains(grbl, "G81")) << grbl;
  EXPECT_TRUE(contains(grbl, "Z-5")) << grbl;
  EXPECT_FALSE(contains(generate("drill --at 1,2 --depth 5 --expand --post rs274ngc"), "G81"));
}

TEST_F(GenCam, DrillErrors) {
  fails("drill --bolt-circle 0,0,30 --depth 5 --post rs274ngc", "E_GEN_BAD_VALUE");
  fails("drill --grid 0,0,2.5,2,10,10 --depth 5 --post rs274ngc", "E_GEN_BAD_VALUE");
  fails("drill --at 1,2 --depth 5 --retract 9 --post rs274ngc", "E_GEN_BAD_VALUE");
}

TEST_F(GenCam, EngraveAndItsErrors) {
  EXPECT_TRUE(contains(generate("engrave --text 'Usina 1' --height 5 --at 10,10 --post rs274ngc"),
                       "Z-0.2"));
  fails("engrave --text 'S\xC3\xA3o' --height 5 --post rs274ngc", "E_TEXT_NOT_IN_FONT");
  fails("engrave --text abc --height 5 --font /no/such.jhf --post rs274ngc", "E_FONT_UNREADABLE");
  fails("engrave --text abc --height 0 --post rs274ngc", "E_GEN_BAD_VALUE");
}

}  // namespace
