// The stock route's query read and bounded (web_stock.hpp): every value
// checked, and an explicit box's grid counted before anything is allocated.
#include <charconv>
#include <cmath>
#include <string_view>

#include <fmt/format.h>

#include "dnc/web_stock.hpp"
#include "sim/stock/words.hpp"

namespace usina::dnc {
namespace {

namespace stock = sim::stock;

tl::unexpected<StockRefusal> refuse(unsigned status, std::string reason) {
  return tl::unexpected(StockRefusal{status, std::move(reason)});
}

const std::string* value_of(const StockQuery& q, std::string_view key) {
  const auto it = q.find(key);
  return it == q.end() ? nullptr : &it->second;
}

tl::expected<std::uint32_t, StockRefusal> frames_of(const StockQuery& q, const StockLimits& l) {
  const std::string* s = value_of(q, "frames");
  if (s == nullptr) return std::min(kDefaultStockFrames, l.max_frames);
  std::uint32_t n = 0;
  const auto [end, ec] = std::from_chars(s->data(), s->data() + s->size(), n);
  if (ec != std::errc() || end != s->data() + s->size() || n < 1 || n > l.max_frames)
    return refuse(400, fmt::format("frames must be a whole number from 1 to {}", l.max_frames));
  return n;
}

tl::expected<std::optional<double>, StockRefusal> resolution_of(const StockQuery& q) {
  const std::string* s = value_of(q, "resolution");
  if (s == nullptr) return std::nullopt;
  const auto r = stock::finite_number(*s);
  if (!r || *r < stock::kMinResolution || *r > stock::kMaxResolution) {
    return refuse(400, fmt::format("resolution must be a number of mm from {:g} to {:g}",
                                   stock::kMinResolution, stock::kMaxResolution));
  }
  return r;
}

// "X,Y,Z": the box's corner at the least X and Y on its top face.
tl::expected<core::Vec3, StockRefusal> origin_of(const std::string& s) {
  double v[3] = {};
  std::string_view rest = s;
  for (int k = 0; k < 3; ++k) {
    const std::size_t comma = k < 2 ? rest.find(',') : std::string_view::npos;
    const auto n = stock::finite_number(rest.substr(0, comma));
    if (!n || (k < 2 && comma == std::string_view::npos))
      return refuse(400, fmt::format("origin '{}' is not X,Y,Z in mm", s));
    v[k] = *n;
    rest = comma == std::string_view::npos ? std::string_view{} : rest.substr(comma + 1);
  }
  return core::Vec3{v[0], v[1], v[2]};
}

tl::expected<std::optional<stock::StockBox>, StockRefusal> box_of(const StockQuery& q) {
  const std::string* spec = value_of(q, "stock");
  const std::string* origin = value_of(q, "origin");
  if (spec == nullptr) {
    if (origin != nullptr)
      return refuse(400, "origin places a stock: give stock=box:WxLxH with it");
    return std::nullopt;
  }
  auto box = stock::parse_stock(*spec);
  if (!box) return refuse(400, box.error());
  if (origin != nullptr) {
    auto o = origin_of(*origin);
    if (!o) return tl::unexpected(o.error());
    box->origin = *o;
  }
  return std::optional<stock::StockBox>(*box);
}

// "T=SHAPE/D;T=SHAPE/D": --tool-shape's values, apart by semicolons (a
// value's own words are apart by commas).
tl::expected<std::map<int, stock::ToolShape>, StockRefusal> tools_of(const StockQuery& q) {
  std::map<int, stock::ToolShape> tools;
  const std::string* s = value_of(q, "tools");
  if (s == nullptr) return tools;
  std::string_view rest = *s;
  while (!rest.empty()) {
    const std::size_t semi = rest.find(';');
    const std::string_view spec = rest.substr(0, semi);
    auto tool = stock::parse_tool_spec(spec, tools);
    if (!tool) return refuse(400, fmt::format("tools: {}", tool.error()));
    tools[tool->first] = tool->second;
    rest = semi == std::string_view::npos ? std::string_view{} : rest.substr(semi + 1);
  }
  return tools;
}

bool known_key(std::string_view key) {
  for (std::string_view k : {"stock", "origin", "resolution", "frames", "tools"})
    if (key == k) return true;
  return false;
}

// The explicit box's grid against the bounds: counted, not allocated.
tl::expected<void, StockRefusal> check_grid(const stock::StockBox& box, double resolution,
                                            std::uint32_t frames, const StockLimits& l) {
  if (auto ok = stock::check_stock(box, resolution); !ok) return refuse(400, ok.error());
  const stock::GridSize g = stock::grid_size(box, resolution);
  const double area = box.width * box.length;
  if (g.cells() > l.max_cells) {
    return refuse(413,
                  fmt::format("a {:g} x {:g} mm stock at {:g} mm is {} x {} = {} cells, more "
                              "than the {} the server simulates: give a coarser resolution "
                              "(at least {:.3g} mm) or a smaller stock",
                              box.width, box.length, resolution, g.nx, g.ny, g.cells(), l.max_cells,
                              std::sqrt(area / static_cast<double>(l.max_cells))));
  }
  if (g.cells() * frames > l.max_cell_frames) {
    return refuse(413, fmt::format("{} cells × {} frames is more than the {} the server sends: "
                                   "ask for fewer frames (at most {}) or a coarser resolution",
                                   g.cells(), frames, l.max_cell_frames,
                                   std::max<std::uint64_t>(1, l.max_cell_frames / g.cells())));
  }
  return {};
}

}  // namespace

tl::expected<StockSettings, StockRefusal> read_stock_query(const StockQuery& query,
                                                           const StockLimits& limits) {
  for (const auto& [key, value] : query) {
    if (!known_key(key))
      return refuse(400, fmt::format("unknown parameter '{}': the stock route takes stock, "
                                     "origin, resolution, frames and tools",
                                     key));
  }
  StockSettings s;
  s.limits = limits;
  auto frames = frames_of(query, limits);
  if (!frames) return tl::unexpected(frames.error());
  s.frames = *frames;
  auto resolution = resolution_of(query);
  if (!resolution) return tl::unexpected(resolution.error());
  s.resolution = *resolution;
  auto box = box_of(query);
  if (!box) return tl::unexpected(box.error());
  s.box = *box;
  auto tools = tools_of(query);
  if (!tools) return tl::unexpected(tools.error());
  s.tools = std::move(*tools);
  if (s.box) {
    const double r = s.resolution ? *s.resolution : 1.0;  // the sides checked first
    if (auto ok = stock::check_stock(*s.box, r); !ok) return refuse(400, ok.error());
    if (!s.resolution) s.resolution = fitting_resolution(*s.box, s.frames, limits, std::nullopt);
    if (auto ok = check_grid(*s.box, *s.resolution, s.frames, limits); !ok)
      return tl::unexpected(ok.error());
  }
  return s;
}

double fitting_resolution(const stock::StockBox& box, std::uint32_t frames,
                          const StockLimits& limits, std::optional<double> asked) {
  const std::uint64_t cap = std::min(limits.max_cells, limits.max_cell_frames / frames);
  const double area = box.width * box.length;
  double r =
      asked ? *asked : std::max(0.1, std::sqrt(area / static_cast<double>(limits.default_cells)));
  // Whole cells round up: a few steps of 1 % find the first that fits.
  while (r < stock::kMaxResolution && stock::grid_size(box, r).cells() > cap)
    r *= 1.01;
  return std::min(r, stock::kMaxResolution);
}

std::string stock_settings_key(const StockSettings& s) {
  std::string key = fmt::format("frames={} resolution={}", s.frames,
                                s.resolution ? fmt::format("{:.17g}", *s.resolution) : "-");
  if (s.box) {
    const stock::StockBox& b = *s.box;
    key += fmt::format(" box={:.17g},{:.17g},{:.17g}@{:.17g},{:.17g},{:.17g}", b.width, b.length,
                       b.height, b.origin.x, b.origin.y, b.origin.z);
  }
  for (const auto& [n, t] : s.tools) {
    key += fmt::format(" T{}={}/{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}", n,
                       stock::shape_name(t), t.diameter, t.corner_radius, t.angle, t.flutes,
                       t.holder, t.stickout, t.plunge_ramp);
  }
  return key;
}

}  // namespace usina::dnc
