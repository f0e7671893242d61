// The stock written out: a binary STL mesh any viewer opens (the height map
// as a closed solid) and the height map as a 16-bit greyscale PNG (docs/simulate.md,
// "Outputs"). Plain C++: the PNG's zlib stream uses stored blocks, so no
// compression library is needed.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "sim/stock/height_map.hpp"

namespace usina::sim::stock {

// An STL holds at most this many triangles (100 MB): a finer map is written
// at a coarser step, each vertex the lowest cell of its block, so no cut
// is hidden.
inline constexpr std::uint64_t kMaxStlTriangles = 2'000'000;

// The step (in cells) an STL of `map` is written at: 1 unless the triangles
// would exceed kMaxStlTriangles.
std::size_t stl_step(const HeightMap& map);

// Writes the stock as a closed binary STL: the top as two triangles per
// cell of the step, four walls and the bottom; returns the triangles written.
std::uint64_t write_stl(const HeightMap& map, std::ostream& out);

// Writes the heights as a 16-bit greyscale PNG, one pixel per cell, +Y up:
// 0 the stock's bottom, 65535 its top.
void write_height_png(const HeightMap& map, std::ostream& out);

// The PNG's checksums (tested on known values).
std::uint32_t crc32(const std::uint8_t* data, std::size_t n, std::uint32_t crc = 0);
std::uint32_t adler32(const std::uint8_t* data, std::size_t n, std::uint32_t adler = 1);

}  // namespace usina::sim::stock
