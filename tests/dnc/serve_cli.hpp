// What the tests of the real `usina serve` process share: spawning it with
// its output in a log, the port it printed, its exit status, and socat's
// pty pair standing in for a serial cable.
#pragma once

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <sys/wait.h>

extern char** environ;

namespace usina::dnc::serve_cli {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

inline std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

inline void write(const fs::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
}

// `usina ARGS...` started with its standard output and error in `log`.
inline pid_t spawn_usina(const std::vector<std::string>& args, const fs::path& log) {
  std::vector<std::string> all{USINA_BINARY};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : all)
    argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  pid_t pid = -1;
  const int rc = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  return rc == 0 ? pid : -1;
}

// The port the server printed ("listening on http://127.0.0.1:PORT"), 0 if none came.
inline unsigned short listening_port(const fs::path& log) {
  const std::regex said("listening on http://127\\.0\\.0\\.1:([0-9]+)");
  for (int i = 0; i < 600; ++i) {
    std::smatch m;
    const std::string text = slurp(log);
    if (std::regex_search(text, m, said)) return static_cast<unsigned short>(std::stoi(m[1]));
    std::this_thread::sleep_for(50ms);
  }
  return 0;
}

inline int wait_exit(pid_t pid) {
  int status = 0;
  if (::waitpid(pid, &status, 0) != pid) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

// socat's pty pair: `machine` for the server, `control` for the simulated CNC.
struct SocatPair {
  fs::path dir;
  pid_t pid = -1;

  bool start() {
    const std::vector<std::string> args{"pty,raw,echo=0,link=" + (dir / "control").string(),
                                        "pty,raw,echo=0,link=" + (dir / "machine").string()};
    std::vector<char*> argv{const_cast<char*>("socat"), const_cast<char*>(args[0].c_str()),
                            const_cast<char*>(args[1].c_str()), nullptr};
    if (posix_spawnp(&pid, "socat", nullptr, nullptr, argv.data(), environ) != 0) return false;
    for (int i = 0; i < 200; ++i) {
      if (fs::exists(dir / "control") && fs::exists(dir / "machine")) return true;
      std::this_thread::sleep_for(25ms);
    }
    return false;
  }

  void stop() {
    if (pid > 0) {
      ::kill(pid, SIGTERM);
      ::waitpid(pid, nullptr, 0);
    }
    pid = -1;
  }

  ~SocatPair() { stop(); }
};

inline std::string config_for(const fs::path& machine_port, int baud = 115200) {
  return "[[machine]]\n"
         "name = \"mill-1\"\n"
         "dialect = \"rs274ngc\"\n"
         "port = \"" +
         machine_port.string() +
         "\"\n"
         "baud = " +
         std::to_string(baud) +
         "\n"
         "data_bits = 8\n"
         "parity = \"none\"\n"
         "stop_bits = 1\n"
         "flow = \"xonxoff\"\n"
         "code = \"ascii\"\n"
         "eob = \"lf\"\n"
         "mode = \"production\"\n"
         "skid = 32\n"
         "leader = 0\n"
         "trailer = 0\n";
}

}  // namespace usina::dnc::serve_cli
