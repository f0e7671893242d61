// `--dialect romi` and `--dialect-option` as a user runs them.
#include <stdio.h>

#include <string>

#include <gtest/gtest.h>
#include <sys/wait.h>

namespace {

struct Result {
  int status = -1;
  std::string out;
};

// Runs `usina <args>` with standard error joined to standard output and
// `input` (no quotes in it) on standard input.
Result usina(const std::string& args, const std::string& input = "") {
  const std::string cmd =
      "printf '%s' '" + input + "' | '" + std::string(USINA_BINARY) + "' " + args + " 2>&1";
  Result r;
  FILE* p = popen(cmd.c_str(), "r");
  EXPECT_NE(p, nullptr);
  if (p == nullptr) return r;
  char buf[4096];
  std::size_t n = 0;
  while ((n = fread(buf, 1, sizeof buf, p)) > 0)
    r.out.append(buf, n);
  const int st = pclose(p);
  r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  return r;
}

const std::string kSeed = std::string("'") + USINA_TEST_DIR + "/programs/romi/seed-000-example.nc'";

TEST(CliRomi, TracesTheSeedProgram) {
  const Result r = usina("trace --dialect romi --format text " + kSeed);
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("hole     at (800.0000, 120.0000, 0.0000) diameter 20 depth 40"),
            std::string::npos);
  EXPECT_NE(r.out.find("W_TYPOGRAPHIC_DASH"), std::string::npos);
}

TEST(CliRomi, DialectOptionChangesTheReading) {
  const Result on = usina("trace --dialect romi -", "G00 X100#x50#M02#");
  EXPECT_EQ(on.status, 0) << on.out;
  EXPECT_NE(on.out.find("\"to\":[150,0,0]"), std::string::npos) << on.out;
  const Result off = usina("trace --dialect romi --dialect-option lowercase_incremental=off -",
                           "G00 X100#x50#M02#");
  EXPECT_EQ(off.status, 0) << off.out;
  EXPECT_NE(off.out.find("\"to\":[50,0,0]"), std::string::npos) << off.out;
}

TEST(CliRomi, UnknownOptionExitsTwoListingTheValidOnes) {
  const Result r = usina("check --dialect romi --dialect-option colour=red " + kSeed);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("usina: error: unknown dialect option 'colour'"), std::string::npos);
  EXPECT_NE(r.out.find("lowercase_incremental=on|off"), std::string::npos) << r.out;
}

TEST(CliRomi, UnknownValueExitsTwoListingTheValidOnes) {
  const Result r = usina("check --dialect romi --dialect-option typographic_dash=maybe " + kSeed);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("typographic_dash takes minus|error, not 'maybe'"), std::string::npos)
      << r.out;
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
