// The pictures of `usina simulate`: the stock shaded, seen from above or in
// an isometric view, coloured by the tool that cut last (rapid cuts red).
#pragma once

#include <cstdio>
#include <string>

#include <tl/expected.hpp>

#include "sim/stock/height_map.hpp"

namespace usina::cli {

enum class StockView { Iso, Top };

// Writes the picture as PNG on `file` (about 1600 pixels wide).
tl::expected<void, std::string> write_stock_png(const sim::stock::HeightMap& map, StockView view,
                                                std::FILE* file);

}  // namespace usina::cli
