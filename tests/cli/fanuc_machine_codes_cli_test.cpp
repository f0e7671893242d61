// Issue 12 §2: a Fanuc machine's own M codes in the trace, written back by
// the posts (not by Grbl's, which would refuse them), drawn nowhere.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "support/usina_process.hpp"

namespace usina {
namespace {

constexpr const char* kProgram = "G0 X0 Y0\nM29 S500\nG1 X10. F100. M59 P2\nM30\n";

TEST(FanucMachineCodesCli, TheTraceShowsTheMachinesCode) {
  const test::TempDir dir;
  const std::string in = dir.write("m.nc", kProgram);
  const test::Run json = test::usina("trace --dialect fanuc " + in);
  ASSERT_EQ(json.status, 0) << json.err;
  EXPECT_THAT(json.out, testing::HasSubstr(R"("op":"machine_code")"));
  EXPECT_THAT(json.out, testing::HasSubstr(R"("code":"M59","p":2)"));
  EXPECT_THAT(json.out, testing::HasSubstr(R"("code":"M29")"));
  const test::Run text = test::usina("trace --format text --dialect fanuc " + in);
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_THAT(text.out, testing::HasSubstr("machine_code M59 P2"));
}

TEST(FanucMachineCodesCli, PostsWriteTheMachinesCodeBack) {
  const test::TempDir dir;
  const std::string in = dir.write("m.nc", kProgram);
  const test::Run fanuc = test::usina("convert --from fanuc " + in + " --post fanuc");
  ASSERT_EQ(fanuc.status, 0) << fanuc.err;
  EXPECT_THAT(fanuc.out, testing::HasSubstr("\nM29\n"));
  EXPECT_THAT(fanuc.out, testing::HasSubstr("\nM59 P2\n"));
  const test::Run grbl = test::usina("convert --from fanuc " + in + " --post grbl");
  EXPECT_EQ(grbl.status, 1);
  EXPECT_THAT(grbl.err, testing::HasSubstr("the grbl post cannot write the machine's M29"));
}

TEST(FanucMachineCodesCli, DrawIgnoresTheMachinesCode) {
  const test::TempDir dir;
  const std::string in = dir.write("m.nc", kProgram);
  const std::string plain = dir.write("p.nc", "G0 X0 Y0\nS500\nG1 X10. F100.\nM30\n");
  const test::Run a = test::usina("draw --dialect fanuc " + in + " -o " + dir.path("a.svg"));
  const test::Run b = test::usina("draw --dialect fanuc " + plain + " -o " + dir.path("b.svg"));
  ASSERT_EQ(a.status, 0) << a.err;
  ASSERT_EQ(b.status, 0) << b.err;
  EXPECT_EQ(test::slurp(dir.path("a.svg")), test::slurp(dir.path("b.svg")));
}

}  // namespace
}  // namespace usina
