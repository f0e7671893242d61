// A POSIX ustar archive written into memory: regular files only, names of
// at most 100 bytes, mode 0644, owner 0. What `GET /api/export` answers, so
// a shop unpacks the released set with `tar x` and checks it with
// `sha256sum -c released.sha256`.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace usina::dnc {

class TarWriter {
 public:
  // False when the name does not fit a ustar header (more than 100 bytes, or empty).
  bool add(std::string_view name, std::string_view bytes, std::int64_t mtime_s);
  // The archive with its end (two zero blocks); the writer is spent.
  std::string finish();

  std::size_t size() const { return out_.size(); }

 private:
  std::string out_;
};

}  // namespace usina::dnc
