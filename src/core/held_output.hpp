// Output for standard output held until the run says it goes out: standard
// output cannot be taken back, and a program with an error must leave
// nothing a machine would take. The bytes wait in an unnamed temporary file
// (core/temporary_file.hpp: in $TMPDIR, else /tmp), so memory stays flat
// however long the output (issue 19: `convert` held 24 MB of program text in
// memory at 1,000,000 blocks, 50 MB with the string's growth).
#pragma once

#include <cstdio>
#include <string>

namespace usina::core {

class HeldOutput {
 public:
  HeldOutput();

  HeldOutput(const HeldOutput&) = delete;
  HeldOutput& operator=(const HeldOutput&) = delete;

  ~HeldOutput() {
    if (file_ != nullptr) std::fclose(file_);
  }

  // Null when no temporary file could be made (the caller says so, with
  // folder() and errno).
  std::FILE* stream() const { return file_; }

  // The folder the file is (or could not be) made in.
  const std::string& folder() const { return folder_; }

  // Copies what was held to `out`; false when it could not all be held
  // (a full temporary folder), read back or written.
  bool send_to(std::FILE* out) const;

 private:
  std::string folder_;
  std::FILE* file_;
};

}  // namespace usina::core
