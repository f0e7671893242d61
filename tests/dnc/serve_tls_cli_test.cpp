// The real `usina serve` process over TLS: the certificate and key named in
// the configuration's [server] table (relative to its folder), the address
// printed as https://, a login through a client that trusts only that
// certificate, and SIGTERM stops it with status 0.
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <unistd.h>

#include <chrono>
#include <regex>
#include <thread>

#include <gtest/gtest.h>
#include <sys/wait.h>

#include "support/files.hpp"
#include "tls_client.hpp"

extern char** environ;

namespace usina::dnc {
namespace {

using namespace std::chrono_literals;

pid_t spawn_usina(std::vector<std::string> args, const std::string& log) {
  args.insert(args.begin(), USINA_BINARY);
  std::vector<char*> argv;
  for (std::string& a : args)
    argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 2, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = -1;
  const int rc = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  return rc == 0 ? pid : -1;
}

int wait_exit(pid_t pid) {
  int status = 0;
  if (::waitpid(pid, &status, 0) != pid) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

// The port of "listening on https://127.0.0.1:PORT", 0 when it did not come in 30 s.
unsigned short https_port(const std::string& log) {
  const std::regex said("listening on https://127\\.0\\.0\\.1:([0-9]+)");
  for (int i = 0; i < 600; ++i) {
    std::smatch m;
    const std::string text = test::slurp(log);
    if (std::regex_search(text, m, said)) return static_cast<unsigned short>(std::stoi(m[1]));
    std::this_thread::sleep_for(50ms);
  }
  return 0;
}

TEST(ServeTlsCli, TheServerTablesCertificateServesHttpsUntilSigterm) {
  const test::TempDir dir;
  ASSERT_TRUE(test::make_self_signed(dir, "server"));
  dir.write("pw", "a long password\n");
  dir.write("usina-serve.toml", "[server]\ntls_cert = \"server.crt\"\ntls_key = \"server.key\"\n");
  const std::string data = dir.path("data");
  ASSERT_EQ(wait_exit(spawn_usina({"serve", "--init", "--data", data, "--admin", "boss",
                                   "--password-file", dir.path("pw")},
                                  dir.path("init.log"))),
            0)
      << dir.read("init.log");
  const pid_t server = spawn_usina({"serve", "--data", data, "--config",
                                    dir.path("usina-serve.toml"), "--listen", "127.0.0.1:0"},
                                   dir.path("serve.log"));
  ASSERT_GT(server, 0);
  const unsigned short port = https_port(dir.path("serve.log"));
  if (port == 0) {
    ::kill(server, SIGKILL);
    wait_exit(server);
    FAIL() << "no https address printed: " << dir.read("serve.log");
  }
  test::TlsClient c(port, dir.path("server.crt"));
  const std::string token = c.log_in("boss", "a long password");
  EXPECT_EQ(token.size(), 64u);
  EXPECT_EQ(c.get("/api/session", token).json()["user"], "boss");
  ::kill(server, SIGTERM);
  EXPECT_EQ(wait_exit(server), 0) << dir.read("serve.log");
  EXPECT_TRUE(test::contains(dir.read("serve.log"), "usina serve: stopped"));
}

}  // namespace
}  // namespace usina::dnc
