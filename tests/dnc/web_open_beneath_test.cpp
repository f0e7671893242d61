// A page file is opened beneath the root one folder at a time (issue 12,
// web_static.hpp open_beneath): the path checked by fs::canonical is the
// one read, and a folder of it that became a symlink after the check is
// not followed. O_NOFOLLOW on the whole path guards only its last name.
#include <fcntl.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "dnc/web_static.hpp"

namespace usina::dnc {
namespace {

namespace fs = std::filesystem;

void write(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << text;
}

std::string read_fd(int fd) {
  std::string out;
  char buf[256];
  for (ssize_t n = 0; (n = ::read(fd, buf, sizeof buf)) > 0;)
    out.append(buf, static_cast<std::size_t>(n));
  ::close(fd);
  return out;
}

class OpenBeneathTest : public ::testing::Test {
 protected:
  void SetUp() override {
    base_ = fs::temp_directory_path() / ("usina_beneath_" + std::to_string(::getpid()));
    fs::remove_all(base_);
    root_ = base_ / "root";
    write(root_ / "img" / "logo.svg", "<svg/>");
    write(base_ / "outside" / "secret.txt", "SECRET");
    root_ = fs::canonical(root_);
  }

  void TearDown() override { fs::remove_all(base_); }

  fs::path base_;
  fs::path root_;
};

TEST_F(OpenBeneathTest, AFileInAFolderOfTheRootIsRead) {
  const int fd = open_beneath(root_, "img/logo.svg");
  ASSERT_GE(fd, 0);
  EXPECT_EQ(read_fd(fd), "<svg/>");
}

TEST_F(OpenBeneathTest, AFolderSwappedForASymlinkAfterTheCheckIsNotFollowed) {
  // The check saw root/img/logo.svg; then img became a symlink out of the root.
  fs::remove_all(root_ / "img");
  write(base_ / "outside" / "logo.svg", "SECRET");
  fs::create_directory_symlink(base_ / "outside", root_ / "img");
  // The old open (O_NOFOLLOW on the whole path) reads through it...
  const int followed = ::open((root_ / "img" / "logo.svg").c_str(), O_RDONLY | O_NOFOLLOW);
  ASSERT_GE(followed, 0);
  EXPECT_EQ(read_fd(followed), "SECRET");
  // ...the open beneath the root does not.
  const int fd = open_beneath(root_, "img/logo.svg");
  EXPECT_LT(fd, 0);
  if (fd >= 0) ::close(fd);
}

TEST_F(OpenBeneathTest, TheLastNameIsNotFollowedEither) {
  fs::create_symlink(base_ / "outside" / "secret.txt", root_ / "secret.txt");
  EXPECT_LT(open_beneath(root_, "secret.txt"), 0);
}

TEST_F(OpenBeneathTest, PathsThatLeaveTheRootAreRefused) {
  EXPECT_LT(open_beneath(root_, "../outside/secret.txt"), 0);
  EXPECT_LT(open_beneath(root_, base_ / "outside" / "secret.txt"), 0);  // absolute
  EXPECT_LT(open_beneath(root_, ""), 0);
}

}  // namespace
}  // namespace usina::dnc
