// Files for tests: a scratch folder per test (TempDir), files read whole,
// and small string helpers. Shared by every test module (tests/support/).
#pragma once

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include <gtest/gtest.h>

namespace usina::test {

inline std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

inline bool exists(const std::string& path) {
  std::error_code ec;
  return std::filesystem::exists(path, ec);
}

inline bool contains(const std::string& s, const std::string& part) {
  return s.find(part) != std::string::npos;
}

// How many times `part` stands in `s`, overlaps counted.
inline std::size_t count(const std::string& s, const std::string& part) {
  std::size_t n = 0;
  for (std::size_t at = s.find(part); at != std::string::npos; at = s.find(part, at + 1))
    ++n;
  return n;
}

inline std::vector<std::string> lines(const std::string& s) {
  std::vector<std::string> out;
  std::istringstream in(s);
  std::string line;
  while (std::getline(in, line))
    out.push_back(line);
  return out;
}

// A scratch folder, /tmp/usina_test_<pid>_<n>, removed with its files when
// it goes out of scope. The process id keeps the test processes ctest runs
// in parallel apart; n keeps apart the folders of one process.
class TempDir {
 public:
  TempDir() {
    static int made = 0;
    path_ = (std::filesystem::temp_directory_path() /
             ("usina_test_" + std::to_string(::getpid()) + "_" + std::to_string(++made)))
                .string();
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);  // left by a crashed process of the same id
    EXPECT_TRUE(std::filesystem::create_directory(path_, ec)) << path_ << ": " << ec.message();
  }

  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
    EXPECT_FALSE(ec) << path_ << ": " << ec.message();
  }

  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const std::string& path() const { return path_; }

  // Where the file `name` is (or will be) in the folder.
  std::string path(const std::string& name) const { return path_ + "/" + name; }

  // Writes `text` to the file `name` and returns its path.
  std::string write(const std::string& name, const std::string& text) const {
    const std::string p = path(name);
    std::ofstream(p, std::ios::binary) << text;
    return p;
  }

  std::string read(const std::string& name) const { return slurp(path(name)); }

 private:
  std::string path_;
};

}  // namespace usina::test
