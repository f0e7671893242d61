// Issue 11, "one vocabulary": the same thing has one name across gen and
// calc (docs/gen.md, "Names"); the old spellings still work for one release,
// with a warning, and the --help texts are English, without source files.
#include <string>
#include <tuple>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "support/usina_process.hpp"

namespace usina {
namespace {

const std::string kDxf = std::string(USINA_TEST_DIR) + "/programs/dxf/arcs_bulges.dxf";

struct Alias {
  std::string old_args;  // the command with the old spelling
  std::string new_args;  // the same with the new one
  std::string new_name;  // what the warning says to use
};

const Alias kAliases[] = {
    {"gen ellipse-pocket --rx 20 --ry 12 --depth 2 --ae 3 --post grbl",
     "gen ellipse-pocket --rx 20 --ry 12 --depth 2 --stepover 3 --post grbl", "--stepover"},
    {"gen ellipse-pocket --rx 20 --ry 12 --depth 2 --stepover 3 --ap 0.5 --post grbl",
     "gen ellipse-pocket --rx 20 --ry 12 --depth 2 --stepover 3 --step-down 0.5 --post grbl",
     "--step-down"},
    {"gen ellipse-pocket --rx 20 --ry 12 --depth 2 --stepover 3 --ae-finish 0.4 --post grbl",
     "gen ellipse-pocket --rx 20 --ry 12 --depth 2 --stepover 3 --finish-allowance 0.4 "
     "--post grbl",
     "--finish-allowance"},
    {"gen ellipse-pocket --rx 20 --ry 12 --depth 2 --stepover 3 --ap-finish 0.3 --post grbl",
     "gen ellipse-pocket --rx 20 --ry 12 --depth 2 --stepover 3 --floor-allowance 0.3 "
     "--post grbl",
     "--floor-allowance"},
    {"gen from-dxf '" + kDxf + "' --post rs274ngc",
     "gen from-dxf --dxf '" + kDxf + "' --post rs274ngc", "--dxf"},
    {"calc cutting --speed 100 --tool-diameter 20",
     "calc cutting --cutting-speed 100 "
     "--tool-diameter 20",
     "--cutting-speed"},
    {"calc cutting --cutting-speed 100 --diameter 20",
     "calc cutting --cutting-speed 100 --tool-diameter 20", "--tool-diameter"},
    {"calc cutting --cutting-speed 100 --tool-diameter 20 --teeth 4 --chip-load 0.05",
     "calc cutting --cutting-speed 100 --tool-diameter 20 --flutes 4 --chip-load 0.05", "--flutes"},
};

TEST(OptionNames, EachOldSpellingStillWorksAndSaysTheNewOne) {
  for (const Alias& a : kAliases) {
    SCOPED_TRACE(a.old_args);
    const test::Run old_run = test::usina(a.old_args);
    const test::Run new_run = test::usina(a.new_args);
    EXPECT_EQ(new_run.status, 0) << new_run.err;
    EXPECT_EQ(old_run.status, 0) << old_run.err;
    EXPECT_EQ(old_run.out, new_run.out);
    EXPECT_FALSE(new_run.out.empty());
    EXPECT_THAT(old_run.err, testing::HasSubstr("deprecated; use " + a.new_name));
    EXPECT_THAT(old_run.err, testing::HasSubstr("[W_DEPRECATED_OPTION]"));
    EXPECT_THAT(new_run.err, testing::Not(testing::HasSubstr("deprecated")));
  }
}

TEST(OptionNames, OldAndNewSpellingTogetherIsAUsageError) {
  const test::Run r =
      test::usina("gen ellipse-pocket --rx 20 --ry 12 --depth 2 --ae 3 --stepover 2 --post grbl");
  EXPECT_NE(r.status, 0);
  EXPECT_TRUE(r.out.empty());
  EXPECT_NE(test::usina("gen from-dxf '" + kDxf + "' --dxf '" + kDxf + "' --post grbl").status, 0);
}

TEST(OptionNames, TheSameOptionHasTheSameDefaultInEveryGenerator) {
  for (const char* gen : {"ellipse-pocket", "from-dxf", "pocket", "profile", "drill", "engrave"}) {
    SCOPED_TRACE(gen);
    const std::string help = test::usina(std::string("gen ") + gen + " --help").out;
    for (const char* option_and_default :
         {"--tool-diameter FLOAT=6 ", "--feed FLOAT=600 ", "--plunge-feed FLOAT=200 ",
          "--rpm FLOAT=10000 ", "--safe-z FLOAT=5 ", "--tool INT:INT in [0 - 99999]=1\n",
          "--max-moves FLOAT=20000000 "}) {
      EXPECT_THAT(help, testing::HasSubstr(option_and_default));
    }
  }
}

TEST(OptionNames, HelpIsEnglishWithoutSourceFilesOrOldNames) {
  for (const char* verb : {"gen", "gen ellipse-pocket", "gen from-dxf", "gen pocket", "gen profile",
                           "gen drill", "gen engrave", "calc", "calc open-loop", "calc closed-loop",
                           "calc precision", "calc cutting", "calc bcd"}) {
    SCOPED_TRACE(verb);
    const test::Run r = test::usina(std::string(verb) + " --help");
    EXPECT_EQ(r.status, 0);
    for (const char* bad : {"src/", ".cpp", ".hpp", "seed 0", "--ae", "--ap", "--teeth",
                            "--diameter", "--speed ", "DRAWING", "Excludes"}) {
      EXPECT_THAT(r.out, testing::Not(testing::HasSubstr(bad))) << bad;
    }
    for (const unsigned char c : r.out)
      EXPECT_LT(c, 0x80) << "a character beyond ASCII";
  }
}

}  // namespace
}  // namespace usina
