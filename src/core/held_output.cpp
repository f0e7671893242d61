#include "core/held_output.hpp"

#include <unistd.h>

#include <cerrno>
#include <vector>

#include "core/temporary_file.hpp"

namespace usina::core {
namespace {

// An unnamed file in `dir` as a stream; null, errno set, when none can be made.
std::FILE* unnamed_file(const std::string& dir) {
  const int fd = open_unnamed_file(dir);
  if (fd < 0) return nullptr;
  std::FILE* f = ::fdopen(fd, "w+b");
  if (f == nullptr) {
    const int why = errno;
    ::close(fd);
    errno = why;
  }
  return f;
}

}  // namespace

HeldOutput::HeldOutput() : folder_(temporary_folder()), file_(unnamed_file(folder_)) {}

bool HeldOutput::send_to(std::FILE* out) const {
  if (file_ == nullptr || std::fflush(file_) != 0 || std::ferror(file_) != 0 ||
      std::fseek(file_, 0, SEEK_SET) != 0)
    return false;
  std::vector<char> buf(std::size_t{1} << 16);
  std::size_t n = 0;
  while ((n = std::fread(buf.data(), 1, buf.size(), file_)) > 0) {
    if (std::fwrite(buf.data(), 1, n, out) != n) return false;
  }
  return std::ferror(file_) == 0 && std::fflush(out) == 0;
}

}  // namespace usina::core
