// A copy of a value of a few hundred bytes taken on every block (the modal
// state a block rolls back to). GCC copies a struct that size with
// `rep movs`, whose start costs more than moving the bytes themselves: 6 %
// of `usina check` for the interpreter's 392-byte state (docs/performance.md).
// Copied sixteen bytes at a time, unrolled, it is a few dozen moves.
#pragma once

#include <cstddef>
#include <cstring>
#include <type_traits>

namespace usina::core {

template <class T>
void copy_in_pieces(T& to, const T& from) {
  static_assert(std::is_trivially_copyable_v<T>);
  constexpr std::size_t kPiece = 16;
  constexpr std::size_t kWhole = sizeof(T) / kPiece * kPiece;
  auto* out = reinterpret_cast<unsigned char*>(&to);
  const auto* in = reinterpret_cast<const unsigned char*>(&from);
#pragma GCC unroll 64
  for (std::size_t i = 0; i < kWhole; i += kPiece)
    std::memcpy(out + i, in + i, kPiece);
  std::memcpy(out + kWhole, in + kWhole, sizeof(T) - kWhole);
}

}  // namespace usina::core
