#include "dnc/tar_writer.hpp"

#include <algorithm>
#include <array>

#include <fmt/format.h>

namespace usina::dnc {
namespace {

constexpr std::size_t kBlock = kTarBlock;

// `value` in octal, zero-padded to `width - 1` digits and a NUL, at `at`.
void octal(std::array<char, kBlock>& h, std::size_t at, std::size_t width, std::uint64_t value) {
  const std::string digits = fmt::format("{:0{}o}", value, width - 1);
  std::copy(digits.begin(), digits.end(), h.begin() + static_cast<std::ptrdiff_t>(at));
}

void text(std::array<char, kBlock>& h, std::size_t at, std::string_view s) {
  std::copy(s.begin(), s.end(), h.begin() + static_cast<std::ptrdiff_t>(at));
}

}  // namespace

std::string tar_header(std::string_view name, std::uint64_t size, std::int64_t mtime_s) {
  if (name.empty() || name.size() > 100) return {};
  std::array<char, kBlock> h{};
  text(h, 0, name);
  octal(h, 100, 8, 0644);  // mode
  octal(h, 108, 8, 0);     // uid
  octal(h, 116, 8, 0);     // gid
  octal(h, 124, 12, size);
  octal(h, 136, 12, static_cast<std::uint64_t>(std::max<std::int64_t>(mtime_s, 0)));
  h[156] = '0';  // a regular file
  text(h, 257,
       std::string_view("ustar\0"
                        "00",
                        8));
  // The checksum: every byte of the header, its own field counted as spaces.
  std::fill(h.begin() + 148, h.begin() + 156, ' ');
  unsigned sum = 0;
  for (const char c : h)
    sum += static_cast<unsigned char>(c);
  octal(h, 148, 7, sum);  // six digits and a NUL, then the space left in place
  return std::string(h.data(), h.size());
}

std::size_t tar_padding(std::uint64_t size) {
  return static_cast<std::size_t>((kBlock - size % kBlock) % kBlock);
}

std::uint64_t tar_member_bytes(std::uint64_t size) {
  return kBlock + size + tar_padding(size);
}

bool TarWriter::add(std::string_view name, std::string_view bytes, std::int64_t mtime_s) {
  const std::string header = tar_header(name, bytes.size(), mtime_s);
  if (header.empty()) return false;
  out_.append(header);
  out_.append(bytes);
  out_.append(tar_padding(bytes.size()), '\0');
  return true;
}

std::string TarWriter::finish() {
  out_.append(2 * kBlock, '\0');
  return std::move(out_);
}

}  // namespace usina::dnc
