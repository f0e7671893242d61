// Issue 11, "Numbers", as a user runs them: a generator parameter out of its
// range or work beyond the limit is a usage error (exit 2) before anything
// is written; a pocket that would leave its core standing is refused; a bad
// tool table value or machine profile value is an error, an unknown profile
// key a warning with the nearest name.
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "support/usina_process.hpp"

namespace usina {
namespace {

const std::string kEllipse =
    "gen ellipse-pocket --rx 30 --ry 20 --depth 5 --tool-diameter 8 --stepover 3 --step-down 2 "
    "--post rs274ngc";

// Runs `args` writing to a file; expects exit 2, `code` on standard error, no file.
void refused(const std::string& args, const std::string& code) {
  const test::TempDir dir;
  const test::Run r = test::usina(args + " -o " + dir.path("out.ngc"));
  EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
  EXPECT_THAT(r.err, testing::HasSubstr(code)) << args;
  EXPECT_FALSE(test::exists(dir.path("out.ngc"))) << args;
}

TEST(GenLimitsCli, EllipseResolutionOfAPicometreIsAnErrorNotAnAbort) {
  // Was std::bad_alloc and SIGABRT (1e-12), 2.4 GB (1e-6), a slot (1e-20).
  for (const char* res : {"1e-12", "1e-20", "1e-6"}) {
    refused(kEllipse + " --resolution " + res, "E_GEN_BAD_VALUE");
    EXPECT_THAT(test::usina(kEllipse + " --resolution " + res).err,
                testing::HasSubstr("give a number from 0.0001 to 100000 mm"));
  }
}

TEST(GenLimitsCli, WorkBeyondTheLimitIsRefusedAndTheLimitCanBeRaised) {
  const test::Run r = test::usina(kEllipse + " --resolution 0.0001");
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.err, testing::HasSubstr("the elliptical pocket would be about 39,996,229 moves "
                                        "(about 720 MB of G-code), more than the limit of "
                                        "20,000,000"));
  EXPECT_THAT(r.err, testing::HasSubstr("[E_GEN_TOO_MUCH_WORK]"));
  refused(kEllipse + " --max-moves 500", "E_GEN_TOO_MUCH_WORK");
  EXPECT_EQ(test::usina(kEllipse + " --max-moves 100000").status, 0);
  refused("gen drill --grid 0,0,300,300,1,1 --depth 5 --peck 0.01 --post rs274ngc",
          "E_GEN_TOO_MUCH_WORK");
  refused(
      "gen pocket --rect 60,40 --depth 3 --stepover 0.05 --step-down 0.01 --max-moves 100000 "
      "--post grbl",
      "E_GEN_TOO_MUCH_WORK");
}

TEST(GenLimitsCli, PocketWhoseFinishAllowanceLeavesTheCoreStandingIsRefused) {
  refused("gen pocket --rect 60,40 --depth 3 --stepover 2 --finish-allowance 30 --post rs274ngc",
          "E_GEN_MATERIAL_LEFT");
  EXPECT_EQ(test::usina("gen pocket --rect 60,40 --depth 3 --stepover 2 --finish-allowance 3 "
                        "--post rs274ngc")
                .status,
            0);
}

TEST(GenLimitsCli, EveryGeneratorRefusesNanInfinityAndAbsurdValues) {
  const std::string commands[] = {
      "gen pocket --rect 60,40 --depth 3 --stepover 2 --post grbl",
      "gen profile --circle 10 --depth 3 --post grbl",
      "gen drill --at 1,1 --depth 3 --post grbl",
      "gen engrave --text A --height 5 --post grbl",
      "gen from-dxf --dxf '" + std::string(USINA_TEST_DIR) +
          "/programs/dxf/arcs_bulges.dxf' "
          "--post grbl",
  };
  for (const std::string& cmd : commands) {
    for (const char* bad : {"--feed nan", "--rpm inf", "--tool-diameter -6", "--safe-z 1e300",
                            "--plunge-feed 0", "--tool-diameter 5000", "--max-moves 0"}) {
      refused(cmd + " " + bad, "E_GEN_BAD_VALUE");
    }
  }
}

TEST(GenLimitsCli, APeckDeeperThanTheHoleIsAWarning) {
  const test::Run r = test::usina("gen drill --at 0,0 --depth 5 --peck 20 --post rs274ngc");
  EXPECT_EQ(r.status, 0);
  EXPECT_THAT(r.err, testing::HasSubstr("[W_GEN_NO_EFFECT]"));
  EXPECT_THAT(r.out, testing::HasSubstr("G83"));
}

TEST(GenLimitsCli, AnOptionThatChangesNothingIsAWarning) {
  const test::Run r =
      test::usina("gen profile --circle 10 --depth 2 --tab-width 4 --corner-radius 2 --post grbl");
  EXPECT_EQ(r.status, 0);
  EXPECT_THAT(r.err, testing::HasSubstr("--tab-width changes nothing without --tabs"));
  EXPECT_THAT(r.err, testing::HasSubstr("--corner-radius changes nothing without --rect"));
  const test::Run quiet = test::usina("gen profile --circle 10 --depth 2 --post grbl");
  EXPECT_TRUE(quiet.err.empty()) << quiet.err;
}

TEST(GenLimitsCli, ANegativeToolDiameterInATableIsAnError) {
  const test::TempDir dir;
  const std::string table = dir.write("t.tbl", "T1 P1 D-6\n");
  const std::string program = dir.write("p.ngc", "G21 G90\nT1 M6\nG81 X0 Y0 Z-1 R1 F100\nM2\n");
  const test::Run r = test::usina("check --tool-table " + table + " " + program);
  EXPECT_NE(r.status, 0);
  EXPECT_THAT(r.err, testing::HasSubstr("t.tbl:1:8: error: diameter D-6 is out of range"));
}

TEST(GenLimitsCli, AMachineProfileWithZeroFeedIsRefusedAnUnknownKeyWarned) {
  const test::TempDir dir;
  std::string vmc =
      test::slurp(std::string(USINA_TEST_DIR) + "/../examples/machines/small_vmc.toml");
  const std::string program = "G21 G90\nG1 X10 F100\nM2\n";
  std::string zero = vmc;
  zero.replace(zero.find("max_feed = 10000.0"), 18, "max_feed = 0");
  test::Run r = test::usina("stats --machine " + dir.write("zero.toml", zero) + " -", program);
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.err, testing::HasSubstr("max_feed = 0 is out of range"));
  std::string typo = vmc;
  typo.replace(typo.find("per_hour"), 8, "per_hours");
  r = test::usina("stats --machine " + dir.write("typo.toml", typo) + " -", program);
  EXPECT_EQ(r.status, 0);
  EXPECT_THAT(r.err, testing::HasSubstr("typo.toml:38:1: warning: unknown key `per_hours` in "
                                        "[cost] is not read; did you mean `per_hour`? "
                                        "[W_UNKNOWN_PROFILE_KEY]"));
}

}  // namespace
}  // namespace usina
