// The stock as a z-map: one height (float) per cell of a regular XY grid,
// sampled at the cell centres. Exact for 3-axis milling with a vertical tool
// (no undercuts: what a vertical tool removes from a column of stock is
// always its top part), W*H*4 bytes, and a sweep touches only the cells
// under its path (docs/simulate.md, "The model").
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <tl/expected.hpp>

#include "core/vec3.hpp"

namespace usina::sim::stock {

// A box of stock: `origin` is its corner at the least X and Y on its top
// face, so the box spans X origin.x..+width, Y origin.y..+length and
// Z origin.z-height..origin.z (the default origin puts the top at Z0).
struct StockBox {
  double width = 0.0;   // X, mm
  double length = 0.0;  // Y, mm
  double height = 0.0;  // Z, mm
  core::Vec3 origin{};
};

// Bounds of the inputs (docs/simulate.md, "Limits").
inline constexpr double kMaxStockSide = 10'000.0;        // mm
inline constexpr double kMaxOriginOffset = 1'000'000.0;  // mm
inline constexpr double kMinResolution = 0.001;          // mm
inline constexpr double kMaxResolution = 100.0;          // mm
inline constexpr std::uint64_t kMaxCells = std::uint64_t{1} << 27;

// "box:200x150x30" -> a box at the default origin; an error says why not.
tl::expected<StockBox, std::string> parse_stock(std::string_view spec);

// Checks a box's numbers and a resolution (finite, within the bounds).
tl::expected<void, std::string> check_stock(const StockBox& box, double resolution);

// The grid a box is divided into at `resolution`: whole cells along X and
// along Y, at least one each (HeightMap::make's, for a caller that bounds
// the cells before asking for a map).
struct GridSize {
  std::uint64_t nx = 0;
  std::uint64_t ny = 0;

  std::uint64_t cells() const { return nx * ny; }
};

GridSize grid_size(const StockBox& box, double resolution);

// Marks of the last cut in a cell: 0 uncut, 1..254 a tool's slot, 255 a rapid.
inline constexpr std::uint8_t kUncut = 0;
inline constexpr std::uint8_t kRapidMark = 255;

class HeightMap {
 public:
  // The grid of `box` with cells at most `resolution` mm a side (the box is
  // divided into whole cells). A grid beyond kMaxCells is refused before
  // anything is allocated: the error names the numbers (E_STOCK_GRID_TOO_LARGE).
  static tl::expected<HeightMap, std::string> make(const StockBox& box, double resolution);

  std::size_t nx() const { return nx_; }

  std::size_t ny() const { return ny_; }

  double dx() const { return dx_; }

  double dy() const { return dy_; }

  double cell_area() const { return dx_ * dy_; }

  double top() const { return top_; }

  double bottom() const { return bottom_; }

  const StockBox& box() const { return box_; }

  // The centre of cell (i, j).
  double x(std::size_t i) const { return x0_ + (static_cast<double>(i) + 0.5) * dx_; }

  double y(std::size_t j) const { return y0_ + (static_cast<double>(j) + 0.5) * dy_; }

  // A cell's height below the top (0 uncut, -height cut through): kept
  // relative to the top so that a float holds it to a micrometre whatever
  // the origin.
  float& at(std::size_t i, std::size_t j) { return h_[j * nx_ + i]; }

  float at(std::size_t i, std::size_t j) const { return h_[j * nx_ + i]; }

  // A cell's Z, mm.
  double z(std::size_t i, std::size_t j) const { return top_ + static_cast<double>(at(i, j)); }

  // For the sweep, the one writer of heights: it calls touch() on the
  // tiles whose cells it lowered.
  float* row(std::size_t j) { return h_.data() + j * nx_; }

  // Tiles of kTile x kTile cells and the highest cell of each: a move whose
  // lowest point over a tile is at or above it cannot cut there, and the
  // sweep passes the whole tile over. Kept lazily: a tile touched is
  // measured again when next asked.
  static constexpr std::size_t kTile = 8;

  std::size_t tiles_x() const { return tx_; }

  std::size_t tiles_y() const { return ty_; }

  float tile_max(std::size_t ti, std::size_t tj);

  void touch(std::size_t ti, std::size_t tj) { tile_dirty_[tj * tx_ + ti] = 1; }

  std::uint8_t* mark_row(std::size_t j) { return mark_.data() + j * nx_; }

  std::uint8_t& mark(std::size_t i, std::size_t j) { return mark_[j * nx_ + i]; }

  std::uint8_t mark(std::size_t i, std::size_t j) const { return mark_[j * nx_ + i]; }

  // The cells whose centres lie in [lo, hi] along X (or Y): first and one
  // past the last; empty (first >= last) when none.
  void columns(double lo, double hi, std::size_t& first, std::size_t& last) const;
  void rows(double lo, double hi, std::size_t& first, std::size_t& last) const;

  // The stock's volume now, mm³ (top down to the heights).
  double volume() const;

  // The volume removed so far: the box's minus volume().
  double removed() const;

 private:
  StockBox box_;
  std::size_t nx_ = 0, ny_ = 0;
  double dx_ = 0.0, dy_ = 0.0, x0_ = 0.0, y0_ = 0.0, top_ = 0.0, bottom_ = 0.0;
  std::vector<float> h_;
  std::vector<std::uint8_t> mark_;
  std::size_t tx_ = 0, ty_ = 0;
  std::vector<float> tile_max_;
  std::vector<std::uint8_t> tile_dirty_;
};

}  // namespace usina::sim::stock
