#include "sim/stock/height_map.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "sim/stock/words.hpp"

namespace usina::sim::stock {
namespace {

bool side_ok(double v) {
  return std::isfinite(v) && v > 0.0 && v <= kMaxStockSide;
}

// Cells of `span` mm at most `resolution` a side: whole cells, at least one.
std::uint64_t cells_across(double span, double resolution) {
  return static_cast<std::uint64_t>(std::max(1.0, std::ceil(span / resolution - 1e-9)));
}

// Indices [first, last) of centres c0 + (k + 0.5) step in [lo, hi], k < n.
void centres_in(double lo, double hi, double c0, double step, std::size_t n, std::size_t& first,
                std::size_t& last) {
  first = last = 0;
  if (!(lo <= hi)) return;
  const double a = std::ceil((lo - c0) / step - 0.5);
  const double b = std::floor((hi - c0) / step - 0.5);
  const double limit = static_cast<double>(n);
  const double fa = std::clamp(a, 0.0, limit);
  const double fb = std::clamp(b + 1.0, 0.0, limit);
  if (fb <= fa) return;
  first = static_cast<std::size_t>(fa);
  last = static_cast<std::size_t>(fb);
}

}  // namespace

tl::expected<StockBox, std::string> parse_stock(std::string_view spec) {
  constexpr std::string_view kBox = "box:";
  if (spec.substr(0, kBox.size()) != kBox) {
    return tl::unexpected(
        fmt::format("'{}' is not a stock: write box:WxLxH in mm, e.g. box:200x150x30", spec));
  }
  std::string_view rest = spec.substr(kBox.size());
  double v[3] = {};
  for (int k = 0; k < 3; ++k) {
    const std::size_t x = k < 2 ? rest.find('x') : std::string_view::npos;
    const auto n = finite_number(rest.substr(0, x));
    if (!n || (k < 2 && x == std::string_view::npos)) {
      return tl::unexpected(
          fmt::format("'{}' is not a stock: write box:WxLxH in mm, e.g. box:200x150x30", spec));
    }
    v[k] = *n;
    rest = x == std::string_view::npos ? std::string_view{} : rest.substr(x + 1);
  }
  return StockBox{v[0], v[1], v[2], {}};
}

tl::expected<void, std::string> check_stock(const StockBox& b, double resolution) {
  if (!side_ok(b.width) || !side_ok(b.length) || !side_ok(b.height)) {
    return tl::unexpected(fmt::format(
        "the stock's sides must be more than 0 and at most {:g} mm, not {:g} x {:g} x {:g}",
        kMaxStockSide, b.width, b.length, b.height));
  }
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(b.origin[i]) || std::abs(b.origin[i]) > kMaxOriginOffset) {
      return tl::unexpected(fmt::format("the stock's origin must be within ±{:g} mm, not {:g}",
                                        kMaxOriginOffset, b.origin[i]));
    }
  }
  if (!std::isfinite(resolution) || resolution < kMinResolution || resolution > kMaxResolution) {
    return tl::unexpected(fmt::format("the resolution must be {:g} to {:g} mm, not {:g}",
                                      kMinResolution, kMaxResolution, resolution));
  }
  return {};
}

GridSize grid_size(const StockBox& box, double resolution) {
  return {cells_across(box.width, resolution), cells_across(box.length, resolution)};
}

tl::expected<HeightMap, std::string> HeightMap::make(const StockBox& box, double resolution) {
  if (auto ok = check_stock(box, resolution); !ok) return tl::unexpected(ok.error());
  const auto [nx, ny] = grid_size(box, resolution);
  if (nx * ny > kMaxCells) {
    return tl::unexpected(fmt::format(
        "a {:g} x {:g} mm stock at {:g} mm is {} x {} = {} cells, more than the {} a height map "
        "may have: give a coarser --resolution (at least {:.3g} mm) or a smaller stock",
        box.width, box.length, resolution, nx, ny, nx * ny, kMaxCells,
        std::sqrt(box.width * box.length / static_cast<double>(kMaxCells))));
  }
  HeightMap m;
  m.box_ = box;
  m.nx_ = static_cast<std::size_t>(nx);
  m.ny_ = static_cast<std::size_t>(ny);
  m.dx_ = box.width / static_cast<double>(nx);
  m.dy_ = box.length / static_cast<double>(ny);
  m.x0_ = box.origin.x;
  m.y0_ = box.origin.y;
  m.top_ = box.origin.z;
  m.bottom_ = box.origin.z - box.height;
  m.h_.assign(m.nx_ * m.ny_, 0.0f);
  m.mark_.assign(m.nx_ * m.ny_, kUncut);
  m.tx_ = (m.nx_ + kTile - 1) / kTile;
  m.ty_ = (m.ny_ + kTile - 1) / kTile;
  m.tile_max_.assign(m.tx_ * m.ty_, 0.0f);
  m.tile_dirty_.assign(m.tx_ * m.ty_, 0);
  return m;
}

float HeightMap::tile_max(std::size_t ti, std::size_t tj) {
  const std::size_t k = tj * tx_ + ti;
  if (tile_dirty_[k] != 0) {
    float high = -std::numeric_limits<float>::infinity();
    for (std::size_t j = tj * kTile; j < std::min(ny_, (tj + 1) * kTile); ++j) {
      const float* r = h_.data() + j * nx_;
      for (std::size_t i = ti * kTile; i < std::min(nx_, (ti + 1) * kTile); ++i) {
        high = std::max(high, r[i]);
      }
    }
    tile_max_[k] = high;
    tile_dirty_[k] = 0;
  }
  return tile_max_[k];
}

void HeightMap::columns(double lo, double hi, std::size_t& first, std::size_t& last) const {
  centres_in(lo, hi, x0_, dx_, nx_, first, last);
}

void HeightMap::rows(double lo, double hi, std::size_t& first, std::size_t& last) const {
  centres_in(lo, hi, y0_, dy_, ny_, first, last);
}

double HeightMap::volume() const {
  double sum = 0.0;
  for (const float h : h_)
    sum += static_cast<double>(h) + box_.height;
  return sum * cell_area();
}

double HeightMap::removed() const {
  double sum = 0.0;
  for (const float h : h_)
    sum -= static_cast<double>(h);
  return sum * cell_area();
}

}  // namespace usina::sim::stock
