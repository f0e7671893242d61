// `usina simulate JOB.toml`: a job file as the program to simulate (docs/
// simulate.md, "Jobs"). The job gives the stock, its tools' shapes from the
// library, and a target depth for each operation that clears an area; its
// canon stream goes to the simulator without a post in between.
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <vector>

#include <tl/expected.hpp>

#include "core/vec3.hpp"
#include "job/load.hpp"
#include "job/sheet.hpp"
#include "sim/stock/height_map.hpp"
#include "sim/stock/target.hpp"
#include "sim/stock/tool_shape.hpp"

namespace usina::cli {

// mm: the chords of a target's arcs and offsets, finer than a grid tells.
inline constexpr double kTargetChord = 0.001;

// A file whose name ends in ".toml" is a job, not an NC program.
bool is_job_file(std::string_view path);

// The closed contours of a layer of a drawing as polygons, arcs in chords
// of `chord` mm; an error when the drawing cannot be read or the layer has
// none (its diagnostics printed on stderr).
tl::expected<std::vector<std::vector<core::Vec2>>, std::string> closed_rings(
    const std::string& dxf, const std::string& layer, double chord);

// The job's stock as the simulation's box: its corner `origin` on the top
// face, Z0. A cylinder is refused (the height map is a box).
tl::expected<sim::stock::StockBox, std::string> job_stock(const job::Job& j);

// The library's tools as the simulation's shapes: end and face mills flat,
// ball and bull nose as they are, drills 118° (or their angle), spot
// drills, chamfer mills and engravers V by their angle; a tap as a drill of
// its core (it cuts the thread, which a height map does not hold); the
// flutes from the cutting length.
tl::expected<std::map<int, sim::stock::ToolShape>, std::string> job_tool_shapes(
    const std::vector<job::Tool>& tools);

// The depths the job's area operations ask for: a pocket's layer (outline
// less islands), an elliptical pocket's ellipse, each as far as its tool
// can reach (the area opened by the tool's radius); a facing's whole top.
// `log`: the steps make_job ran (each operation's tool).
tl::expected<std::vector<sim::stock::TargetLayer>, std::string> job_targets(
    const job::LoadedJob& j, const job::SheetLog& log);

}  // namespace usina::cli
