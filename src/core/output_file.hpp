// Every file usina writes goes through here, so that no output destroys what
// it should not (docs/cli.md):
// - a regular file is written to a new temporary beside it (O_EXCL |
//   O_NOFOLLOW, a random name), flushed, fsynced and renamed over the target
//   only when the whole output is good; the target keeps its mode (and, as
//   root, its owner);
// - a character device or a FIFO (a serial port, /dev/null, a pipe) is
//   written in place, never replaced; a block device is refused;
// - a symbolic link is followed when it belongs to the user or to root, and
//   refused when it belongs to someone else (it could point anywhere);
// - an existing file the user could not write, were they not root, is
//   refused, as is an output that is one of the run's inputs (same device
//   and inode), before anything is written.
#pragma once

#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <sys/types.h>
#include <tl/expected.hpp>

namespace usina::core {

// A file's identity: two paths name one file when these agree.
struct FileId {
  dev_t dev = 0;
  ino_t ino = 0;
};

class OutputFile {
 public:
  // Opens `path` for writing. `inputs` are the paths the run reads; the
  // output may not be one of them. The error says why, with the path.
  static tl::expected<OutputFile, std::string> open(const std::string& path,
                                                    const std::vector<std::string>& inputs = {});

  // File descriptor 1 as an OutputFile, so that a full disk or a closed
  // pipe under standard output is seen, with its reason, by commit().
  static tl::expected<OutputFile, std::string> standard_output();

  OutputFile(OutputFile&& other) noexcept;
  OutputFile& operator=(OutputFile&&) = delete;
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;
  // Without a commit, the temporary is removed and the target left as it was.
  ~OutputFile();

  // Buffered; write freely, every error is seen by commit().
  std::FILE* stream() const { return stream_; }

  const std::string& path() const { return path_; }

  // Why a write failed ("cannot write PATH: No space left on device"), after
  // flushing what is buffered; nullopt while every write has succeeded.
  std::optional<std::string> write_error();

  // Flushes, syncs and puts the output in place. An error (a full disk, a
  // device gone) leaves the target as it was when it was a regular file.
  tl::expected<void, std::string> commit();

 private:
  struct Descriptor;  // the fd under stream_ and why its first write failed

  OutputFile() = default;
  tl::expected<void, std::string> attach(int fd);
  tl::expected<void, std::string> close_stream();
  void discard();

  std::string path_;     // as the user wrote it, for messages
  std::string target_;   // the file replaced (symbolic links resolved)
  std::string partial_;  // the temporary; empty when written in place
  std::FILE* stream_ = nullptr;
  std::unique_ptr<Descriptor> descriptor_;
  bool keep_owner_ = false;
  mode_t mode_ = 0;
  uid_t uid_ = 0;
  gid_t gid_ = 0;
};

// The whole of `text` written to `path` through an OutputFile.
tl::expected<void, std::string> write_file(const std::string& path, std::string_view text,
                                           const std::vector<std::string>& inputs = {});

// Fails, with a message naming `path`, when `path` is the file `input` names.
tl::expected<void, std::string> check_not_input(const std::string& path, const std::string& input);

}  // namespace usina::core
