#include "core/held_output.hpp"

#include <vector>

namespace usina::core {

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
