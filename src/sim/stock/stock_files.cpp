#include "sim/stock/stock_files.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

#include "core/vec3.hpp"

namespace usina::sim::stock {
namespace {

using core::Vec3;

void put_u32_le(std::ostream& out, std::uint32_t v) {
  const std::array<char, 4> b = {static_cast<char>(v & 0xff), static_cast<char>((v >> 8) & 0xff),
                                 static_cast<char>((v >> 16) & 0xff),
                                 static_cast<char>((v >> 24) & 0xff)};
  out.write(b.data(), 4);
}

void put_f32(std::ostream& out, double v) {
  const auto f = static_cast<float>(v);
  std::uint32_t bits = 0;
  std::memcpy(&bits, &f, 4);
  put_u32_le(out, bits);
}

// One facet, its normal from the right-hand order of its corners.
void facet(std::ostream& out, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 u = b - a, v = c - a;
  Vec3 n{u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x};
  const double len = core::norm(n);
  if (len > 0.0) n = n / len;
  for (const Vec3& p : {n, a, b, c}) {
    put_f32(out, p.x);
    put_f32(out, p.y);
    put_f32(out, p.z);
  }
  out.write("\0\0", 2);
}

// The vertex grid of an STL at `step`: vertices at the block centres, the
// outer ones on the stock's faces, each the lowest cell of its block.
struct Grid {
  std::size_t nx = 0, ny = 0;
  std::vector<double> xs, ys, z;

  Vec3 at(std::size_t i, std::size_t j) const { return {xs[i], ys[j], z[j * nx + i]}; }
};

std::vector<double> axis(std::size_t cells, std::size_t step, double origin, double size,
                         double cell) {
  std::vector<double> v;
  for (std::size_t k = 0; k < cells; k += step) {
    const std::size_t end = std::min(cells, k + step);
    v.push_back(origin + 0.5 * static_cast<double>(k + end) * cell);
  }
  v.front() = origin;
  if (v.size() == 1) v.push_back(origin + size);
  v.back() = origin + size;
  return v;
}

Grid grid_of(const HeightMap& m, std::size_t step) {
  Grid g;
  const StockBox& b = m.box();
  g.xs = axis(m.nx(), step, b.origin.x, b.width, m.dx());
  g.ys = axis(m.ny(), step, b.origin.y, b.length, m.dy());
  g.nx = g.xs.size();
  g.ny = g.ys.size();
  g.z.assign(g.nx * g.ny, m.top());
  const std::size_t bx = (m.nx() + step - 1) / step, by = (m.ny() + step - 1) / step;
  for (std::size_t j = 0; j < g.ny; ++j) {
    for (std::size_t i = 0; i < g.nx; ++i) {
      // A map one block wide has two vertices on it: both take that block.
      const std::size_t ci = std::min(i, bx - 1), cj = std::min(j, by - 1);
      double low = m.top();
      for (std::size_t y = cj * step; y < std::min(m.ny(), (cj + 1) * step); ++y) {
        for (std::size_t x = ci * step; x < std::min(m.nx(), (ci + 1) * step); ++x) {
          low = std::min(low, m.z(x, y));
        }
      }
      g.z[j * g.nx + i] = low;
    }
  }
  return g;
}

std::uint64_t triangles_of(std::uint64_t nx, std::uint64_t ny) {
  return 2 * (nx - 1) * (ny - 1) + 4 * ((nx - 1) + (ny - 1)) + 2 * ((nx - 1) + (ny - 1));
}

// The walls and the bottom (a fan from its centre over the boundary's vertices).
void walls(const Grid& g, double bottom, std::ostream& out) {
  std::vector<Vec3> ring;  // counter-clockwise seen from above
  for (std::size_t i = 0; i + 1 < g.nx; ++i)
    ring.push_back(g.at(i, 0));
  for (std::size_t j = 0; j + 1 < g.ny; ++j)
    ring.push_back(g.at(g.nx - 1, j));
  for (std::size_t i = g.nx - 1; i > 0; --i)
    ring.push_back(g.at(i, g.ny - 1));
  for (std::size_t j = g.ny - 1; j > 0; --j)
    ring.push_back(g.at(0, j));
  const Vec3 centre{0.5 * (g.xs.front() + g.xs.back()), 0.5 * (g.ys.front() + g.ys.back()), bottom};
  for (std::size_t k = 0; k < ring.size(); ++k) {
    const Vec3 a = ring[k], b = ring[(k + 1) % ring.size()];
    const Vec3 a0{a.x, a.y, bottom}, b0{b.x, b.y, bottom};
    facet(out, a, a0, b0);
    facet(out, a, b0, b);
    facet(out, centre, b0, a0);
  }
}

void chunk(std::ostream& out, const char* type, const std::vector<std::uint8_t>& data) {
  const auto n = static_cast<std::uint32_t>(data.size());
  const std::array<char, 4> len = {static_cast<char>(n >> 24), static_cast<char>((n >> 16) & 0xff),
                                   static_cast<char>((n >> 8) & 0xff), static_cast<char>(n & 0xff)};
  out.write(len.data(), 4);
  out.write(type, 4);
  out.write(reinterpret_cast<const char*>(data.data()), static_cast<std::streamsize>(n));
  std::uint32_t crc = crc32(reinterpret_cast<const std::uint8_t*>(type), 4);
  crc = crc32(data.data(), data.size(), crc);
  const std::array<char, 4> c = {
      static_cast<char>(crc >> 24), static_cast<char>((crc >> 16) & 0xff),
      static_cast<char>((crc >> 8) & 0xff), static_cast<char>(crc & 0xff)};
  out.write(c.data(), 4);
}

void put_be32(std::vector<std::uint8_t>& v, std::uint32_t x) {
  for (int s = 24; s >= 0; s -= 8)
    v.push_back(static_cast<std::uint8_t>((x >> s) & 0xff));
}

// A zlib stream of stored (uncompressed) blocks.
std::vector<std::uint8_t> stored_zlib(const std::vector<std::uint8_t>& raw) {
  std::vector<std::uint8_t> z = {0x78, 0x01};
  std::size_t at = 0;
  do {
    const std::size_t n = std::min<std::size_t>(65535, raw.size() - at);
    const bool last = at + n == raw.size();
    z.push_back(last ? 1 : 0);
    z.push_back(static_cast<std::uint8_t>(n & 0xff));
    z.push_back(static_cast<std::uint8_t>(n >> 8));
    z.push_back(static_cast<std::uint8_t>(~n & 0xff));
    z.push_back(static_cast<std::uint8_t>((~n >> 8) & 0xff));
    z.insert(z.end(), raw.begin() + static_cast<std::ptrdiff_t>(at),
             raw.begin() + static_cast<std::ptrdiff_t>(at + n));
    at += n;
  } while (at < raw.size());
  put_be32(z, adler32(raw.data(), raw.size()));
  return z;
}

}  // namespace

std::uint32_t crc32(const std::uint8_t* data, std::size_t n, std::uint32_t crc) {
  static const std::array<std::uint32_t, 256> table = [] {
    std::array<std::uint32_t, 256> t{};
    for (std::uint32_t i = 0; i < 256; ++i) {
      std::uint32_t c = i;
      for (int k = 0; k < 8; ++k)
        c = (c & 1) != 0 ? 0xedb88320u ^ (c >> 1) : c >> 1;
      t[i] = c;
    }
    return t;
  }();
  crc = ~crc;
  for (std::size_t i = 0; i < n; ++i)
    crc = table[(crc ^ data[i]) & 0xff] ^ (crc >> 8);
  return ~crc;
}

std::uint32_t adler32(const std::uint8_t* data, std::size_t n, std::uint32_t adler) {
  std::uint32_t a = adler & 0xffff, b = adler >> 16;
  for (std::size_t i = 0; i < n; ++i) {
    a = (a + data[i]) % 65521;
    b = (b + a) % 65521;
  }
  return (b << 16) | a;
}

std::size_t stl_step(const HeightMap& map) {
  std::size_t step = 1;
  while (triangles_of((map.nx() + step - 1) / step + 1, (map.ny() + step - 1) / step + 1) >
         kMaxStlTriangles) {
    ++step;
  }
  return step;
}

std::uint64_t write_stl(const HeightMap& map, std::ostream& out) {
  const Grid g = grid_of(map, stl_step(map));
  const std::uint64_t n = triangles_of(g.nx, g.ny);
  std::array<char, 80> header{};
  std::snprintf(header.data(), header.size(), "usina simulate: stock");
  out.write(header.data(), 80);
  put_u32_le(out, static_cast<std::uint32_t>(n));
  for (std::size_t j = 0; j + 1 < g.ny; ++j) {
    for (std::size_t i = 0; i + 1 < g.nx; ++i) {
      facet(out, g.at(i, j), g.at(i + 1, j), g.at(i + 1, j + 1));
      facet(out, g.at(i, j), g.at(i + 1, j + 1), g.at(i, j + 1));
    }
  }
  walls(g, map.bottom(), out);
  return n;
}

void write_height_png(const HeightMap& map, std::ostream& out) {
  const std::size_t w = map.nx(), h = map.ny();
  std::vector<std::uint8_t> raw;
  raw.reserve(h * (1 + 2 * w));
  const double height = map.box().height;
  for (std::size_t r = 0; r < h; ++r) {
    const std::size_t j = h - 1 - r;  // the first row is the highest Y
    raw.push_back(0);                 // filter: none
    for (std::size_t i = 0; i < w; ++i) {
      const double t = std::clamp((static_cast<double>(map.at(i, j)) + height) / height, 0.0, 1.0);
      const auto v = static_cast<std::uint16_t>(std::lround(t * 65535.0));
      raw.push_back(static_cast<std::uint8_t>(v >> 8));
      raw.push_back(static_cast<std::uint8_t>(v & 0xff));
    }
  }
  static const std::array<char, 8> signature = {'\x89', 'P', 'N', 'G', '\r', '\n', '\x1a', '\n'};
  out.write(signature.data(), 8);
  std::vector<std::uint8_t> ihdr;
  put_be32(ihdr, static_cast<std::uint32_t>(w));
  put_be32(ihdr, static_cast<std::uint32_t>(h));
  ihdr.insert(ihdr.end(), {16, 0, 0, 0, 0});  // 16 bits, greyscale, deflate, none, no interlace
  chunk(out, "IHDR", ihdr);
  chunk(out, "IDAT", stored_zlib(raw));
  chunk(out, "IEND", {});
}

}  // namespace usina::sim::stock
