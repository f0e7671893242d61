// usina gen ellipse-pocket: the golden program per post, the round trip
// through usina's interpreter in each control's dialect, the input errors.
#include <string>
#include <utility>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "support/usina_process.hpp"

namespace usina {
namespace {

const std::string kGolden = std::string(USINA_TEST_DIR) + "/programs/post/ellipse_small.";
const std::string kArgs =
    "gen ellipse-pocket --center 10,5 --rx 6 --ry 4 --depth 2 --tool-diameter 3 --stepover 1.2 "
    "--step-down 1 --finish-allowance 0.3 --floor-allowance 0.4 --resolution 1 --feed 400 "
    "--plunge-feed 100 --rpm 2000 "
    "--safe-z 3 --program-name ellipse_small";

struct Golden {
  const char* post;
  const char* ext;
};

constexpr Golden kPosts[] = {
    {"rs274ngc", "ngc"}, {"fanuc", "nc"}, {"grbl", "gcode"}, {"romi", "nc"}};

std::string golden(const Golden& g) {
  return kGolden + g.post + "." + g.ext;
}

TEST(GenEllipseCli, EveryPostWritesItsGoldenProgram) {
  for (const Golden& g : kPosts) {
    const test::Run r = test::usina(kArgs + " --post " + g.post);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out, test::slurp(golden(g))) << g.post;
  }
}

TEST(GenEllipseCli, WritesTheOutputFile) {
  const test::TempDir dir;
  const std::string out = dir.path("ellipse.ngc");
  const test::Run r = test::usina(kArgs + " --post rs274ngc -o " + out);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(test::slurp(out), test::slurp(golden(kPosts[0])));
}

// The rs274ngc program read back moves as the generator's canon does (the
// in-process test in tests/cam proves that); each other control's program,
// read by usina in that control's dialect, must move the same. A dialect
// the interpreter does not read yet skips.
TEST(GenEllipseCli, RoundTripInEachDialect) {
  const test::Run reference = test::usina("trace " + golden(kPosts[0]));
  ASSERT_EQ(reference.status, 0) << reference.err;
  std::vector<std::string> skipped;
  for (const Golden& g : kPosts) {
    const test::Run r = test::usina(std::string("trace --dialect ") + g.post + " " + golden(g));
    if (r.status != 0 && r.err.find("--dialect") != std::string::npos) {
      skipped.push_back(g.post);
      continue;
    }
    ASSERT_EQ(r.status, 0) << g.post << "\n" << r.err;
    SCOPED_TRACE(g.post);
    test::expect_same_motion(reference.out, r.out, 2e-3);
  }
  if (!skipped.empty())
    GTEST_SKIP() << "dialects not read yet: " << testing::PrintToString(skipped);
}

TEST(GenEllipseCli, BadInputIsAUsageError) {
  const std::string base =
      "gen ellipse-pocket --center 0,0 --rx 10 --ry 6 --depth 3 --step-down 1 --post grbl ";
  const std::pair<std::string, std::string> cases[] = {
      {"--tool-diameter 12 --stepover 2", "not narrower than the minor axis"},
      {"--tool-diameter 4 --stepover 5", "bigger than the tool diameter"},
      {"--tool-diameter 4 --stepover 2 --resolution 6", "not smaller than the radii"},
      {"--tool-diameter 4 --stepover -2", "the stepover (--stepover) is -2 mm; give a number"},
      {"--tool-diameter 4 --stepover 2 --feed 0", "the feed (--feed) is 0 mm/min; give a number"},
  };
  for (const auto& [args, message] : cases) {
    const test::Run r = test::usina(base + args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_THAT(r.err, testing::StartsWith("usina: error: gen ellipse-pocket: ")) << args;
    EXPECT_THAT(r.err, testing::HasSubstr(message)) << args;
    EXPECT_TRUE(r.out.empty());
  }
  EXPECT_NE(test::usina("gen ellipse-pocket --center 1 --rx 10 --ry 6 --depth 3 --step-down 1 "
                        "--tool-diameter 4 --stepover 2 --post grbl")
                .status,
            0);                             // --center needs X,Y
  EXPECT_NE(test::usina("gen").status, 0);  // a generator is required
  const test::Run no_stepover =
      test::usina("gen ellipse-pocket --rx 10 --ry 6 --depth 3 --post grbl");
  EXPECT_NE(no_stepover.status, 0);
  EXPECT_THAT(no_stepover.err, testing::HasSubstr("--stepover"));
}

}  // namespace
}  // namespace usina
