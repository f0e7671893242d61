// The usina binary run as a user runs it (the CLI and server tests), and
// the motion of two traces compared (spec/trace.md). Scratch folders and
// file helpers: support/files.hpp.
#pragma once

#include <stdio.h>  // popen, pclose (POSIX)
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sys/wait.h>

#include "support/files.hpp"

namespace usina::test {

// Single-quotes `s` for /bin/sh.
inline std::string quote(const std::string& s) {
  std::string out = "'";
  for (const char c : s)
    out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

struct Run {
  int status = -1;  // the exit status, 128 + the signal when one ended it
  std::string out;
  std::string err;
};

// The /bin/sh command `cmd`, whose standard error goes to the file `err`.
inline Run shell(const std::string& cmd, const std::string& err) {
  Run r;
  FILE* p = popen(cmd.c_str(), "r");
  EXPECT_NE(p, nullptr) << cmd;
  if (p == nullptr) return r;
  char buf[4096];
  std::size_t n = 0;
  while ((n = fread(buf, 1, sizeof buf, p)) > 0)
    r.out.append(buf, n);
  const int st = pclose(p);
  r.status = WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st);
  r.err = slurp(err);
  return r;
}

// Runs `usina <args>` (args already quoted for /bin/sh) with `input` on
// standard input; standard output and standard error are kept apart.
inline Run usina(const std::string& args, const std::string& input = "") {
  const TempDir io;
  const std::string in = io.write("stdin", input);
  const std::string err = io.path("stderr");
  return shell(quote(USINA_BINARY) + " " + args + " <" + quote(in) + " 2>" + quote(err), err);
}

// The motion ops of a jsonl trace, moves that go nowhere dropped.
inline std::vector<nlohmann::json> motion(const std::string& trace) {
  std::vector<nlohmann::json> out;
  std::istringstream in(trace);
  std::string line;
  std::vector<double> at;
  while (std::getline(in, line)) {
    nlohmann::json j = nlohmann::json::parse(line);
    const std::string op = j["op"];
    if (op != "traverse" && op != "feed" && op != "arc" && op != "probe" && op != "dwell") continue;
    if (op != "dwell") {
      const std::vector<double> to = j["to"];
      if (op != "arc" && !at.empty() &&
          std::hypot(to[0] - at[0], to[1] - at[1], to[2] - at[2]) < 1e-4)
        continue;
      at = to;
    }
    out.push_back(std::move(j));
  }
  return out;
}

inline void expect_close(const nlohmann::json& a, const nlohmann::json& b, const char* key,
                         double tol, std::size_t i) {
  const std::vector<double> va = a[key];
  const std::vector<double> vb = b[key];
  for (std::size_t k = 0; k < va.size(); ++k)
    EXPECT_NEAR(va[k], vb[k], tol) << "motion op " << i << " " << key << ": " << a << " vs " << b;
}

// Same motion within `tol` mm (the post's decimals): ops, end points, arc
// centres and turns.
inline void expect_same_motion(const std::string& trace_a, const std::string& trace_b, double tol) {
  const auto a = motion(trace_a);
  const auto b = motion(trace_b);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a[i]["op"], b[i]["op"]) << "motion op " << i;
    if (a[i]["op"] == "dwell") continue;
    expect_close(a[i], b[i], "to", tol, i);
    if (a[i]["op"] == "arc") {
      expect_close(a[i], b[i], "center", tol, i);
      EXPECT_EQ(a[i]["turn"], b[i]["turn"]) << "motion op " << i;
    }
  }
}

}  // namespace usina::test
