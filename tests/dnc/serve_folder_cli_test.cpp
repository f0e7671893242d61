// `usina serve --import DIR` and `--export DIR`: a shop's folder of programs
// into the store in one command, the released set out, each in the audit
// log under a store user whose role allows it.
#include <string>

#include <gtest/gtest.h>

#include "dnc/store.hpp"
#include "dnc/store_audit.hpp"
#include "dnc/store_users.hpp"
#include "support/usina_process.hpp"

namespace usina::dnc {
namespace {

using test::quote;
using test::TempDir;

// A SQLite store in `dir`/data with the admin boss (made by `serve --init`).
std::string init_store(const TempDir& dir) {
  dir.write("pw", "a long enough password\n");
  const std::string data = dir.path("data");
  const auto r = test::usina("serve --init --data " + quote(data) +
                             " --admin boss --password-file " + quote(dir.path("pw")));
  EXPECT_EQ(r.status, 0) << r.err;
  return data;
}

TEST(ServeFolderCli, EachFileBecomesARevisionAndASecondRunFindsThemThere) {
  const TempDir dir;
  const std::string data = init_store(dir);
  const TempDir shop;
  shop.write("O1001.nc", "G21 G90\nG0 X10 Y10\nG1 Z-1 F100\nM2\n");
  shop.write("O1002.ngc", "G21 G90\nG0 X5\nM2\n");
  const std::string args = "serve --data " + quote(data) + " --import " + quote(shop.path()) +
                           " --user boss --dialect rs274ngc";
  const auto first = test::usina(args);
  EXPECT_EQ(first.status, 0) << first.err;
  EXPECT_TRUE(test::contains(first.out, "O1001.nc: program O1001, revision ")) << first.out;
  EXPECT_TRUE(test::contains(first.out, "O1002.ngc: program O1002, revision ")) << first.out;
  EXPECT_TRUE(test::contains(first.err, "2 imported, 0 there already, 0 skipped")) << first.err;
  const auto again = test::usina(args);
  EXPECT_EQ(again.status, 0) << again.err;
  EXPECT_TRUE(test::contains(again.err, "0 imported, 2 there already, 0 skipped")) << again.err;
  // The audit log names the user and says the import came from a shell.
  auto store = Store::open(data);
  ASSERT_TRUE(store) << store.error().message;
  const auto chain = verify_audit(**store);
  ASSERT_TRUE(chain);
  EXPECT_TRUE(chain->ok);
}

TEST(ServeFolderCli, ASkippedFileIsSaidAndTheExitStatusIsOne) {
  const TempDir dir;
  const std::string data = init_store(dir);
  const TempDir shop;
  shop.write("O1001.nc", "G0 X1\nM2\n");
  shop.write("bad name.nc", "G0 X1\nM2\n");
  shop.write("esc\x1b[2Jape.nc", "G0 X1\nM2\n");  // a name that would clear a terminal
  const auto r = test::usina("serve --data " + quote(data) + " --import " + quote(shop.path()) +
                             " --user boss");
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_TRUE(test::contains(r.out, "bad name.nc: skipped: ")) << r.out;
  EXPECT_TRUE(test::contains(r.out, "esc\\x1b[2Jape.nc: skipped: ")) << r.out;
  EXPECT_FALSE(test::contains(r.out, "\x1b")) << "a control byte reached the terminal";
  EXPECT_TRUE(test::contains(r.err, "1 imported, 0 there already, 2 skipped")) << r.err;
}

TEST(ServeFolderCli, TheUserMustExistBeEnabledAndHaveTheRole) {
  const TempDir dir;
  const std::string data = init_store(dir);
  {
    auto store = Store::open(data);
    ASSERT_TRUE(store);
    ASSERT_TRUE(create_user(**store, "op", Role::Operator, "another long password", {"boss", "t"}));
  }
  const TempDir shop;
  shop.write("O1.nc", "G0 X1\nM2\n");
  const std::string base = "serve --data " + quote(data) + " --import " + quote(shop.path());
  const auto none = test::usina(base);
  EXPECT_EQ(none.status, 2);
  EXPECT_TRUE(test::contains(none.err, "needs --user NAME")) << none.err;
  const auto stranger = test::usina(base + " --user nobody");
  EXPECT_EQ(stranger.status, 2);
  EXPECT_TRUE(test::contains(stranger.err, "--user nobody: ")) << stranger.err;
  const auto op = test::usina(base + " --user op");
  EXPECT_EQ(op.status, 2);
  EXPECT_TRUE(test::contains(op.err, "--user op is operator: that role may not import")) << op.err;
  EXPECT_EQ(test::usina(base + " --user boss --dialect klingon").status, 2);
}

TEST(ServeFolderCli, TheReleasedSetGoesOutWithItsChecksumList) {
  const TempDir dir;
  const std::string data = init_store(dir);
  const TempDir out;
  const std::string folder = out.path("released");
  const auto r = test::usina("serve --data " + quote(data) + " --export " + quote(folder) +
                             " --user boss --extension tap");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(test::exists(folder + "/released.sha256"));
  EXPECT_TRUE(test::contains(r.err, "0 released programs written to")) << r.err;
  const auto bad = test::usina("serve --data " + quote(data) + " --export " + quote(folder) +
                               " --user boss --extension ../x");
  EXPECT_EQ(bad.status, 2);
  EXPECT_TRUE(test::contains(bad.err, "--extension ../x: 1 to 8 letters or digits")) << bad.err;
}

TEST(ServeFolderCli, OneTaskAtATime) {
  const TempDir dir;
  const auto r = test::usina("serve --data " + quote(dir.path("data")) +
                             " --verify-audit --import " + quote(dir.path()) + " --user boss");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(test::contains(r.err, "one at a time")) << r.err;
}

}  // namespace
}  // namespace usina::dnc
