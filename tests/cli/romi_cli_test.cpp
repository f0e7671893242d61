// `--dialect romi` and `--dialect-option` as a user runs them.
#include <string>

#include <gtest/gtest.h>

#include "support/usina_process.hpp"

namespace {

using usina::test::usina;
using Result = usina::test::Run;

const std::string kSeed = std::string("'") + USINA_TEST_DIR + "/programs/romi/seed-000-example.nc'";

TEST(CliRomi, TracesTheSeedProgram) {
  const Result r = usina("trace --dialect romi --format text " + kSeed);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("hole     at (800.0000, 120.0000, 0.0000) diameter 20 depth 40"),
            std::string::npos);
  EXPECT_NE(r.err.find("W_TYPOGRAPHIC_DASH"), std::string::npos) << r.err;
}

TEST(CliRomi, DialectOptionChangesTheReading) {
  const Result on = usina("trace --dialect romi -", "G00 X100#x50#M02#");
  EXPECT_EQ(on.status, 0) << on.err;
  EXPECT_NE(on.out.find("\"to\":[150,0,0]"), std::string::npos) << on.out;
  const Result off = usina("trace --dialect romi --dialect-option lowercase_incremental=off -",
                           "G00 X100#x50#M02#");
  EXPECT_EQ(off.status, 0) << off.err;
  EXPECT_NE(off.out.find("\"to\":[50,0,0]"), std::string::npos) << off.out;
}

TEST(CliRomi, UnknownOptionExitsTwoListingTheValidOnes) {
  const Result r = usina("check --dialect romi --dialect-option colour=red " + kSeed);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("usina: error: unknown dialect option 'colour'"), std::string::npos);
  EXPECT_NE(r.err.find("lowercase_incremental=on|off"), std::string::npos) << r.err;
}

TEST(CliRomi, UnknownValueExitsTwoListingTheValidOnes) {
  const Result r = usina("check --dialect romi --dialect-option typographic_dash=maybe " + kSeed);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("typographic_dash takes minus|error, not 'maybe'"), std::string::npos)
      << r.err;
}

TEST(CliRomi, NotNameEqualsValueExitsTwo) {
  const Result r = usina("check --dialect romi --dialect-option lowercase_incremental " + kSeed);
  EXPECT_EQ(r.status, 2);
}

TEST(CliRomi, UnknownDialectIsRefused) {
  const Result r = usina("check --dialect heidenhain " + kSeed);
  EXPECT_NE(r.status, 0);
}

}  // namespace
