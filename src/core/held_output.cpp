#include "core/held_output.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <vector>

namespace usina::core {
namespace {

std::string temporary_folder() {
  const char* dir = std::getenv("TMPDIR");
  return dir != nullptr && *dir != '\0' ? dir : "/tmp";
}

// An unnamed file in `dir`: O_TMPFILE where the file system has it, else a
// named one removed at once. Null, errno set, when neither can be made.
std::FILE* unnamed_file(const std::string& dir) {
  int fd = ::open(dir.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0600);
  if (fd < 0 && (errno == EOPNOTSUPP || errno == EISDIR)) {
    std::string name = dir + "/usina-held-XXXXXX";
    fd = ::mkostemp(name.data(), O_CLOEXEC);
    if (fd >= 0) ::unlink(name.c_str());
  }
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
