// kill -9 of a process in the middle of an upload, on both back ends: the
// store shows whole revisions only (with their audit entries) and takes the
// next upload.
#include <poll.h>
#include <signal.h>
#include <unistd.h>

#include <random>
#include <set>
#include <thread>

#include <gtest/gtest.h>
#include <sys/wait.h>

#include "dnc/store_audit.hpp"
#include "dnc/store_revisions.hpp"
#include "store_fixture.hpp"

namespace usina::dnc {
namespace {

// A program of about `kb` kilobytes, different for each `n`.
std::string program(int n, int kb) {
  std::string text = "(program " + std::to_string(n) + ")\nG21 G90 G0 X0 Y0 Z5\n";
  for (int i = 0; text.size() < static_cast<std::size_t>(kb) * 1024; ++i)
    text += "G1 X" + std::to_string(i % 97) + " Y" + std::to_string(n) + " F500\n";
  return text + "M2\n";
}

class StoreCrash : public test::StoreTest {
 protected:
  // Waits for a byte from the child; false after a minute without one.
  static bool wait_byte(int fd) {
    pollfd p{fd, POLLIN, 0};
    char c = 0;
    return ::poll(&p, 1, 60'000) == 1 && ::read(fd, &c, 1) == 1;
  }

  static void kill_child(pid_t pid) {
    ::kill(pid, SIGKILL);
    int status = 0;
    ::waitpid(pid, &status, 0);
  }

  // After the crash: every revision whole, every upload audited, the chain intact.
  void expect_consistent(Store& s, std::size_t at_least) {
    const auto revisions = list_revisions(s, {}).value();
    EXPECT_GE(revisions.size(), at_least);
    for (const Revision& v : revisions) {
      auto bytes = revision_bytes(s, v.program, v.hash);
      ASSERT_TRUE(bytes) << bytes.error().message;
      EXPECT_EQ(static_cast<std::int64_t>(bytes->size()), v.size);
      EXPECT_TRUE(CheckResults::from_json(v.checks_json));
    }
    const auto v = verify_audit(s).value();
    EXPECT_TRUE(v.ok) << v.problem;
    EXPECT_EQ(static_cast<std::size_t>(v.entries), revisions.size());
    // No blob without its revision (one blob may serve several programs).
    std::set<std::string> hashes;
    for (const Revision& r : revisions)
      hashes.insert(r.hash);
    auto blobs = raw()->query("SELECT COUNT(*) FROM blobs").value();
    EXPECT_EQ(static_cast<std::size_t>(blobs[0].integer(0)), hashes.size());
  }
};

TEST_P(StoreCrash, KilledBetweenTheBlobAndTheRevisionLeavesNothing) {
  { ASSERT_TRUE(open()); }  // the schema, made before the child starts
  int fds[2];
  ASSERT_EQ(::pipe(fds), 0);
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    StoreOptions o = options();
    o.hook = [fd = fds[1]](std::string_view point) {
      if (point != "upload.blob-written") return;
      [[maybe_unused]] const auto n = ::write(fd, "x", 1);
      for (;;)
        ::pause();  // killed here, inside the transaction
    };
    auto s = Store::open(where(), o);
    if (s)
      (void)put_revision(**s, {"BIG", "", "rs274ngc", program(1, 2048), "r", nullptr},
                         {"ana", "t"});
    ::_exit(1);
  }
  ::close(fds[1]);
  ASSERT_TRUE(wait_byte(fds[0])) << "the child never reached the blob";
  kill_child(pid);
  ::close(fds[0]);
  auto s = open();
  ASSERT_TRUE(s);
  EXPECT_FALSE(find_program(*s, "BIG"));
  expect_consistent(*s, 0);
  // The lock died with the process: the next upload goes through.
  EXPECT_TRUE(
      put_revision(*s, {"BIG", "", "rs274ngc", program(1, 64), "r", nullptr}, {"ana", "t"}));
}

TEST_P(StoreCrash, KilledAtARandomMomentOfManyUploadsLeavesWholeRevisions) {
  { ASSERT_TRUE(open()); }
  std::mt19937 rng(GetParam() == Backend::Sqlite ? 1 : 2);
  for (int round = 0; round < 3; ++round) {
    int fds[2];
    ASSERT_EQ(::pipe(fds), 0);
    const pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      auto s = Store::open(where(), options());
      for (int n = 0; s; ++n) {
        const std::string name = "R" + std::to_string(round) + "N" + std::to_string(n);
        if (!put_revision(**s, {name, "", "rs274ngc", program(round * 1000 + n, 256), "r", nullptr},
                          {"ana", "t"}))
          break;
        [[maybe_unused]] const auto w = ::write(fds[1], "x", 1);
      }
      ::_exit(1);
    }
    ::close(fds[1]);
    ASSERT_TRUE(wait_byte(fds[0]));
    ASSERT_TRUE(wait_byte(fds[0]));
    std::this_thread::sleep_for(
        std::chrono::microseconds(std::uniform_int_distribution<int>(0, 30'000)(rng)));
    kill_child(pid);
    ::close(fds[0]);
  }
  auto s = open();
  ASSERT_TRUE(s);
  expect_consistent(*s, 6);
}

USINA_STORE_BACKENDS(StoreCrash);

}  // namespace
}  // namespace usina::dnc
