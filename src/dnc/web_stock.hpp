// The stock a revision leaves, for the web page's viewer (docs/web.md, "The
// stock"): the program runs through the interpreter in its dialect and
// `usina simulate`'s StockSimulator cuts a box of stock with it; the height
// map is taken at N points of the program (equal shares of its moves), so
// the page replays the removal frame by frame. The answer is compact: a
// small JSON header, then each frame as the cells that changed since the
// frame before (16-bit depths below the top and the mark of the tool that
// cut them), so the stock uncut plus every frame's changes is the final map.
//
// What a request may ask is bounded before anything is allocated: the
// cells of the grid, the frames and cells × frames (the frames' work); the
// answer's bytes are bounded as the frames are taken.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>

#include <tl/expected.hpp>

#include "sim/stock/height_map.hpp"
#include "sim/stock/tool_shape.hpp"

namespace usina::dnc {

// The server's bounds (docs/web.md, "The stock"): anyone who may read
// programs may ask, so no request may exhaust the memory or the pool.
struct StockLimits {
  std::uint64_t max_cells = 4'000'000;         // 20 MB of map, 12 MB more for the frames
  std::uint32_t max_frames = 64;               // the slider's steps
  std::uint64_t max_cell_frames = 32'000'000;  // cells × frames: the frames' work
  // The answer's bytes: a program that changes most cells in most frames
  // (3 bytes a cell, 8 a run) is refused past this, 413, when it is reached.
  std::uint64_t max_answer_bytes = 64u << 20;
  std::uint64_t default_cells = 250'000;  // the grid when no resolution is asked
};

inline constexpr std::uint32_t kDefaultStockFrames = 16;

struct StockSettings {
  std::string dialect = "rs274ngc";
  // None: the box is the program's (docs/web.md): its cuts' XY extent grown
  // by the largest tool radius, top at Z0, down to the deepest cut + 1 mm.
  std::optional<sim::stock::StockBox> box;
  std::optional<double> resolution;  // mm; none: the coarsest of 0.1 and default_cells
  std::uint32_t frames = kDefaultStockFrames;
  std::map<int, sim::stock::ToolShape> tools;  // by number; others from the program or 6 mm flat
  std::uint64_t max_ops = 100'000'000;         // canon operations, as the check
  StockLimits limits;
};

// A request refused: 400 for a malformed value, 413 for a grid or an answer
// too large, with the reason.
struct StockRefusal {
  unsigned status = 400;
  std::string reason;
};

using StockQuery = std::map<std::string, std::string, std::less<>>;

// `stock=box:WxLxH`, `origin=X,Y,Z` (with a stock only), `resolution=R`,
// `frames=N`, `tools=T=SHAPE/D;T=SHAPE/D` of the route's query, checked
// against `limits` (the explicit box's grid is counted, never allocated).
tl::expected<StockSettings, StockRefusal> read_stock_query(const StockQuery& query,
                                                           const StockLimits& limits);

// The resolution of `box`: the one asked, or when none is, the coarser of
// 0.1 mm and about default_cells cells; then made coarser until the grid
// is within max_cells and max_cell_frames / frames.
double fitting_resolution(const sim::stock::StockBox& box, std::uint32_t frames,
                          const StockLimits& limits, std::optional<double> asked);

// The settings as the cache's key: equal settings, equal answers.
std::string stock_settings_key(const StockSettings& s);

// The answer's bytes (little-endian): "USSK", version, the header's length,
// the JSON header (padded with spaces to 4 bytes), then each frame's runs,
// depths and marks at the offsets the header gives. When the program's own
// box cannot be a stock (a side beyond 10 m, 422) or the frames grow past
// max_answer_bytes (413), the bytes are a JSON object {"error": reason,
// "status": code} instead (is_stock_answer tells them apart).
std::string encode_stock(std::string_view text, const StockSettings& settings);

bool is_stock_answer(std::string_view bytes);

inline constexpr std::uint32_t kStockMagic = 0x4B535355;  // "USSK" little-endian
inline constexpr std::uint32_t kStockVersion = 1;

}  // namespace usina::dnc
