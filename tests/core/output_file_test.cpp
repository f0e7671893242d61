// core::OutputFile: no output ever destroys what it should not (issue 11).
#include "core/output_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <thread>

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>

#include "support/usina_process.hpp"

namespace usina::core {
namespace {

using test::contains;
using test::slurp;
using test::TempDir;

struct stat stat_of(const std::string& path) {
  struct stat st {};

  EXPECT_EQ(::lstat(path.c_str(), &st), 0) << path;
  return st;
}

// The files of a folder, so a test can see that no temporary was left.
std::vector<std::string> names_in(const std::string& folder) {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::directory_iterator(folder))
    out.push_back(e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

bool is_root() {
  return ::geteuid() == 0;
}

TEST(OutputFile, NewFileGetsTheUmaskModeAndNoTemporaryIsLeft) {
  const TempDir dir;
  const mode_t mask = ::umask(022);
  ASSERT_TRUE(write_file(dir.path("out.ngc"), "G0 X1\n"));
  ::umask(mask);
  EXPECT_EQ(slurp(dir.path("out.ngc")), "G0 X1\n");
  EXPECT_EQ(stat_of(dir.path("out.ngc")).st_mode & 07777, 0644u);
  EXPECT_EQ(names_in(dir.path()), std::vector<std::string>{"out.ngc"});
}

TEST(OutputFile, ReplacedFileKeepsItsMode) {
  const TempDir dir;
  const std::string out = dir.write("out.ngc", "old\n");
  ASSERT_EQ(::chmod(out.c_str(), 0640), 0);
  ASSERT_TRUE(write_file(out, "new\n"));
  EXPECT_EQ(slurp(out), "new\n");
  EXPECT_EQ(stat_of(out).st_mode & 07777, 0640u);
}

TEST(OutputFile, WithoutCommitTheTargetIsUntouchedAndTheTemporaryGone) {
  const TempDir dir;
  const std::string out = dir.write("out.ngc", "old\n");
  {
    auto f = OutputFile::open(out);
    ASSERT_TRUE(f) << f.error();
    std::fputs("half a progr", f->stream());
  }
  EXPECT_EQ(slurp(out), "old\n");
  EXPECT_EQ(names_in(dir.path()), std::vector<std::string>{"out.ngc"});
}

// The old writer opened OUT.partial-<pid> with O_CREAT|O_TRUNC: a link
// planted under that name sent root's output anywhere.
TEST(OutputFile, APlantedPartialNameCannotRedirectTheWrite) {
  const TempDir dir;
  const std::string victim = dir.write("victim", "keep me\n");
  const std::string out = dir.path("out.ngc");
  const std::string planted = out + ".partial-" + std::to_string(::getpid());
  ASSERT_EQ(::symlink(victim.c_str(), planted.c_str()), 0);
  ASSERT_TRUE(write_file(out, "program\n"));
  EXPECT_EQ(slurp(victim), "keep me\n");
  EXPECT_EQ(slurp(out), "program\n");
}

TEST(OutputFile, TheOutputMayNotBeAnInput) {
  const TempDir dir;
  const std::string program = dir.write("p.ngc", "G0 X1\nM2\n");
  const auto r = write_file(program, "x", {program});
  ASSERT_FALSE(r);
  EXPECT_TRUE(contains(r.error(), "also an input")) << r.error();
  EXPECT_EQ(slurp(program), "G0 X1\nM2\n");
}

TEST(OutputFile, AnInputUnderAnotherNameIsStillAnInput) {
  const TempDir dir;
  const std::string program = dir.write("p.ngc", "G0 X1\nM2\n");
  const std::string hard = dir.path("hard.ngc");
  const std::string soft = dir.path("soft.ngc");
  ASSERT_EQ(::link(program.c_str(), hard.c_str()), 0);
  ASSERT_EQ(::symlink(program.c_str(), soft.c_str()), 0);
  EXPECT_FALSE(write_file(hard, "x", {program}));
  EXPECT_FALSE(write_file(soft, "x", {program}));
  EXPECT_FALSE(write_file(program, "x", {dir.path(".") + "/p.ngc"}));
  EXPECT_EQ(slurp(program), "G0 X1\nM2\n");
}

TEST(OutputFile, ALinkOfTheUsersOwnIsFollowedAndStaysALink) {
  const TempDir dir;
  const std::string real = dir.write("real.ngc", "old\n");
  const std::string link = dir.path("link.ngc");
  ASSERT_EQ(::symlink("real.ngc", link.c_str()), 0);
  ASSERT_TRUE(write_file(link, "new\n"));
  EXPECT_TRUE(S_ISLNK(stat_of(link).st_mode));
  EXPECT_EQ(slurp(real), "new\n");
}

TEST(OutputFile, ALinkOfAnotherUserIsRefused) {
  if (!is_root()) GTEST_SKIP() << "needs root to give a link to another user";
  const TempDir dir;
  const std::string victim = dir.write("victim", "keep me\n");
  const std::string link = dir.path("out.ngc");
  ASSERT_EQ(::symlink(victim.c_str(), link.c_str()), 0);
  ASSERT_EQ(::lchown(link.c_str(), 12345, 12345), 0);
  const auto r = write_file(link, "x");
  ASSERT_FALSE(r);
  EXPECT_TRUE(contains(r.error(), "belongs to another user")) << r.error();
  EXPECT_EQ(slurp(victim), "keep me\n");
}

TEST(OutputFile, AReadOnlyFileIsRefused) {
  const TempDir dir;
  const std::string out = dir.write("out.ngc", "keep me\n");
  if (is_root()) {
    ASSERT_EQ(::chown(out.c_str(), 12345, 12345), 0);  // another owner's
    ASSERT_EQ(::chmod(out.c_str(), 0644), 0);
  } else {
    ASSERT_EQ(::chmod(out.c_str(), 0444), 0);
  }
  const auto r = write_file(out, "x");
  ASSERT_FALSE(r);
  EXPECT_TRUE(contains(r.error(), "read-only for you")) << r.error();
  EXPECT_EQ(slurp(out), "keep me\n");
}

TEST(OutputFile, AFolderIsRefusedAndAMissingFolderNamed) {
  const TempDir dir;
  const auto folder = write_file(dir.path(), "x");
  ASSERT_FALSE(folder);
  EXPECT_TRUE(contains(folder.error(), "is a folder")) << folder.error();
  const auto missing = write_file(dir.path("nodir/x.png"), "x");
  ASSERT_FALSE(missing);
  EXPECT_TRUE(contains(missing.error(), dir.path("nodir/x.png"))) << missing.error();
  EXPECT_TRUE(contains(missing.error(), "No such file or directory")) << missing.error();
}

TEST(OutputFile, ACharacterDeviceIsWrittenInPlaceNotReplaced) {
  if (!is_root()) GTEST_SKIP() << "needs root to make a device node";
  const TempDir dir;
  const std::string null = dir.path("null");
  if (::mknod(null.c_str(), S_IFCHR | 0666, makedev(1, 3)) != 0)
    GTEST_SKIP() << "mknod: " << std::strerror(errno);
  ASSERT_TRUE(write_file(null, "G0 X1\n"));
  EXPECT_TRUE(S_ISCHR(stat_of(null).st_mode));
  EXPECT_EQ(names_in(dir.path()), std::vector<std::string>{"null"});
}

TEST(OutputFile, ABlockDeviceIsRefused) {
  if (!is_root()) GTEST_SKIP() << "needs root to make a device node";
  const TempDir dir;
  const std::string disk = dir.path("disk");
  if (::mknod(disk.c_str(), S_IFBLK | 0600, makedev(7, 200)) != 0)
    GTEST_SKIP() << "mknod: " << std::strerror(errno);
  const auto r = write_file(disk, "x");
  ASSERT_FALSE(r);
  EXPECT_TRUE(contains(r.error(), "block device")) << r.error();
}

TEST(OutputFile, AFifoIsWrittenInPlaceNotReplaced) {
  const TempDir dir;
  const std::string fifo = dir.path("fifo");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::string got;
  std::thread reader([&] { got = slurp(fifo); });
  const auto r = write_file(fifo, "G0 X1\n");
  reader.join();
  ASSERT_TRUE(r) << r.error();
  EXPECT_EQ(got, "G0 X1\n");
  EXPECT_TRUE(S_ISFIFO(stat_of(fifo).st_mode));
}

TEST(OutputFile, AFullDeviceIsAnErrorAtCommit) {
  struct stat st {};

  if (::stat("/dev/full", &st) != 0 || !S_ISCHR(st.st_mode)) GTEST_SKIP() << "no /dev/full";
  const auto r = write_file("/dev/full", std::string(1 << 20, 'x'));
  ASSERT_FALSE(r);
  EXPECT_TRUE(contains(r.error(), "No space left on device")) << r.error();
  EXPECT_TRUE(S_ISCHR(stat_of("/dev/full").st_mode));
}

}  // namespace
}  // namespace usina::core
