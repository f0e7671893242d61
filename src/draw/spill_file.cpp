#include "draw/spill_file.hpp"

#include <unistd.h>

#include <cerrno>
#include <utility>

#include "core/temporary_file.hpp"

namespace usina::draw {

SpillFile::SpillFile(std::string folder)
    : folder_(folder.empty() ? core::temporary_folder() : std::move(folder)) {}

void SpillFile::set_folder(std::string folder) {
  if (fd_ < 0) folder_ = folder.empty() ? core::temporary_folder() : std::move(folder);
}

SpillFile::~SpillFile() {
  if (fd_ >= 0) ::close(fd_);
}

std::optional<std::uint64_t> SpillFile::append(const std::vector<char>& bytes) {
  if (failed_) return std::nullopt;
  if (fd_ < 0) fd_ = core::open_unnamed_file(folder_);
  std::size_t done = 0;
  while (fd_ >= 0 && done < bytes.size()) {
    const ssize_t n =
        ::pwrite(fd_, bytes.data() + done, bytes.size() - done, static_cast<off_t>(size_ + done));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    done += static_cast<std::size_t>(n);
  }
  if (fd_ < 0 || done < bytes.size()) {
    failed_ = true;
    return std::nullopt;
  }
  return std::exchange(size_, size_ + bytes.size());
}

int SpillFile::read(char* out, std::size_t n, std::uint64_t offset) const {
  while (n > 0) {
    const ssize_t got = ::pread(fd_, out, n, static_cast<off_t>(offset));
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) return errno;
    if (got == 0) return EIO;
    out += got;
    n -= static_cast<std::size_t>(got);
    offset += static_cast<std::uint64_t>(got);
  }
  return 0;
}

}  // namespace usina::draw
