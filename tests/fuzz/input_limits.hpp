// Loop limits of the fuzz targets that run programs, scaled to the input.
// A loop's body can be the whole input, so with -max_len at 1 MiB a fixed
// limit of 20,000 iterations would let one input do 20 GB of work and time
// out without any defect. The limit shrinks with the input instead, keeping
// the work of all iterations together near what it is for a 1 KB input.
#pragma once

#include <algorithm>
#include <cstddef>

namespace usina::fuzz {

// `full` iterations for inputs up to 1 KB, fewer above (at least 16).
inline long iterations_for(long full, std::size_t input_size) {
  constexpr std::size_t kWork = 20'000'000;  // input bytes × iterations
  const auto by_size = static_cast<long>(kWork / std::max<std::size_t>(input_size, 1));
  return std::min(full, std::max(16L, by_size));
}

}  // namespace usina::fuzz
