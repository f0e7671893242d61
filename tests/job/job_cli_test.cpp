// usina job as a user runs it: each example job posted for every control,
// read back by `usina check --dialect` and timed by `usina stats` on the
// job's machine; a bad job file's diagnostic shows its file and line.
#include <gtest/gtest.h>

#include "job_test_util.hpp"
#include "support/files.hpp"
#include "support/usina_process.hpp"

namespace usina::job {
namespace {

using test::quote;

constexpr const char* kPosts[] = {"rs274ngc", "fanuc", "grbl", "romi"};

void posted_checked_timed(const std::string& example, int tool_changes) {
  const std::string job = testing::repo("examples/jobs/" + example);
  const std::string machine = testing::repo("examples/machines/small_vmc.toml");
  for (const char* post : kPosts) {
    SCOPED_TRACE(post);
    const test::TempDir dir;
    const std::string out = dir.path("part.nc");
    const test::Run made =
        test::usina("job " + quote(job) + " --post " + post + " -o " + quote(out));
    ASSERT_EQ(made.status, 0) << made.err;
    const test::Run checked =
        test::usina(std::string("check --dialect ") + post + " " + quote(out));
    EXPECT_EQ(checked.status, 0) << checked.err << checked.out;
    const test::Run timed = test::usina(std::string("stats --dialect ") + post + " --machine " +
                                        quote(machine) + " " + quote(out));
    EXPECT_EQ(timed.status, 0) << timed.err;
    // grbl has no tool changer: the post writes each change as a comment
    // and an M0 pause, which stats does not count as a change.
    const int changes = std::string(post) == "grbl" ? 0 : tool_changes;
    EXPECT_NE(timed.out.find("tool changes " + std::to_string(changes)), std::string::npos)
        << timed.out;
  }
}

TEST(JobCli, PlatePostedCheckedTimedForEveryControl) {
  posted_checked_timed("plate.toml", 4);
}

TEST(JobCli, EllipseCoverPostedCheckedTimedForEveryControl) {
  posted_checked_timed("ellipse_cover.toml", 1);
}

TEST(JobCli, TheProgramSaysWhyEachNumber) {
  const test::Run r =
      test::usina("job " + quote(testing::repo("examples/jobs/plate.toml")) + " --post rs274ngc");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("n = vc*1000/[pi*D] = 243.84*1000/[pi*6] = 12936"), std::string::npos);
  EXPECT_NE(r.out.find("max_rpm 10000 caps n"), std::string::npos);
  EXPECT_NE(r.out.find("Torbide"), std::string::npos);
  EXPECT_NE(r.out.find("chosen: T2"), std::string::npos);
}

TEST(JobCli, ABadJobIsExitOneWithItsFileAndLine) {
  const test::TempDir dir;
  const std::string job = dir.write(
      "bad.toml", testing::job_text("[[operation]]\ntype = \"pocket\"\nlayer = \"POCKET\"\n"
                                    "dept = 3.0\ntool = 2\n"));
  const std::string out = dir.path("part.nc");
  const test::Run r = test::usina("job " + quote(job) + " --post rs274ngc -o " + quote(out));
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("bad.toml:13:1"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("E_UNKNOWN_JOB_KEY"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));  // no half program
}

TEST(JobCli, AnUnreadableJobIsExitTwo) {
  const test::TempDir dir;
  const test::Run r = test::usina("job " + quote(dir.path("none.toml")) + " --post rs274ngc");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("cannot read"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace usina::job
