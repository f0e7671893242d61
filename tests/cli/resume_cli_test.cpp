// usina resume (docs/resume.md): the restart program written through the
// output file; refusals exit 1 with the reason; usage errors exit 2.
#include <string>

#include <gtest/gtest.h>

#include "support/usina_process.hpp"

namespace usina::test {
namespace {

constexpr const char* kProgram = "G21 G90\nT1 M6\nS900 M3\nG0 X1 Y1 Z5\nG1 Z-1 F300\nG1 X5\nM2\n";

TEST(ResumeCli, WritesThePreambleAndTheRestFromALine) {
  const TempDir dir;
  const std::string p = dir.write("p.ngc", kProgram);
  const std::string out = dir.path() + "/r.ngc";
  const test::Run r = usina("resume --block 6 " + quote(p) + " -o " + quote(out));
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string got = slurp(out);
  EXPECT_TRUE(contains(got, "(restart at line 6)\n")) << got;
  EXPECT_TRUE(contains(got, "G0 X1 Y1\nG1 Z-1 F300\nG1 X5\nM2\n")) << got;
}

TEST(ResumeCli, ARefusedStartIsExit1WithTheReasonAndWritesNothing) {
  const TempDir dir;
  const std::string p = dir.write("p.ngc", kProgram);
  const std::string out = dir.path() + "/r.ngc";
  const test::Run r = usina("resume --tool 4 " + quote(p) + " -o " + quote(out));
  EXPECT_EQ(r.status, 1);
  EXPECT_TRUE(contains(r.err, "tool T4 is never")) << r.err;
  EXPECT_FALSE(exists(out));
}

TEST(ResumeCli, UsageErrorsAreExit2) {
  const TempDir dir;
  const std::string p = dir.write("p.ngc", kProgram);
  EXPECT_EQ(usina("resume " + quote(p) + " -o " + quote(dir.path() + "/r")).status, 2);
  EXPECT_EQ(usina("resume --block X1 " + quote(p) + " -o " + quote(dir.path() + "/r")).status, 2);
  const test::Run self = usina("resume --block 3 " + quote(p) + " -o " + quote(p));
  EXPECT_EQ(self.status, 2);
  EXPECT_EQ(slurp(p), kProgram) << "the input is never overwritten";
}

TEST(ResumeCli, HelpListsTheVerb) {
  EXPECT_TRUE(contains(usina("help").out, "resume"));
}

}  // namespace
}  // namespace usina::test
