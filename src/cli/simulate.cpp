// usina simulate FILE --stock box:WxLxH: cuts a stock with the program's
// tools (a z-map, exact sweeps) and reports the volume removed per tool,
// the rapids that cut and the cuts below a floor; writes the stock as STL,
// pictures (PNG), the height map (16-bit PNG) and a JSON report
// (docs/simulate.md).
//
// Exit status: 0; 1 when the program has an error or a check failed (a
// rapid cutting stock, a cut below the floor); 2 for bad input (an
// unreadable program, a bad option, a grid too large, an unwritable output).
#include <charconv>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/machine_option.hpp"
#include "cli/raster_module.hpp"
#include "cli/run.hpp"
#include "cli/simulate_job.hpp"
#include "cli/verbs.hpp"
#include "core/file_ostream.hpp"
#include "core/output_file.hpp"
#include "core/units.hpp"
#include "gcode/tool_table.hpp"
#include "job/make.hpp"
#include "sim/stats.hpp"
#include "sim/stock/removal_rate.hpp"
#include "sim/stock/simulator.hpp"
#include "sim/stock/stock_files.hpp"
#include "sim/stock/target.hpp"

namespace usina::cli {
namespace {

using nlohmann::json;
namespace stock = sim::stock;

struct SimulateOptions {
  RunOptions run;
  std::string stock;
  std::vector<double> origin;
  double resolution = 0.1;
  std::vector<std::string> tool_shapes;  // T=SHAPE[/D]
  std::optional<double> floor;
  std::vector<std::string> outputs;
  std::string height_map;
  std::string view = "iso";
  std::string target_dxf;
  std::vector<std::string> targets;  // LAYER=Z
  double target_tolerance = 0.01;
  std::string machine;  // profile for the times (docs/stats.md); empty: the generic mill
};

// mm: a target deeper or higher than this is no part's.
constexpr double kMaxTargetZ = 1e5;

constexpr int kBadInput = 2;

int fail(const std::string& message) {
  fmt::print(stderr, "usina: error: {}\n", message);
  return kBadInput;
}

// Counts the errors of the run and of the checks, and keeps the checks' locations
// printable: every diagnostic is rendered on stderr by the run's printer.
class Errors final : public core::DiagnosticSink {
 public:
  void set_sources(const core::SourceManager* s) { sources_ = s; }

  void report(core::Diagnostic d) override {
    if (d.severity == core::Severity::Error) ++errors_;
    if (sources_ != nullptr) {
      const std::string text = core::render(d, *sources_);
      std::fwrite(text.data(), 1, text.size(), stderr);
    }
  }

  int errors() const { return errors_; }

 private:
  const core::SourceManager* sources_ = nullptr;
  int errors_ = 0;
};

// The tool table's tools with their shapes (a word of the comment), then
// --tool-shape T=SHAPE[/D] over them.
tl::expected<std::map<int, stock::ToolShape>, std::string> tool_shapes(
    const SimulateOptions& o, std::map<int, stock::ToolShape> tools) {
  if (!o.run.tool_table.empty()) {
    std::string err;
    auto file = core::SourceFile::open(o.run.tool_table, err);
    if (!file) return tl::unexpected(fmt::format("cannot read {}: {}", o.run.tool_table, err));
    core::DiagnosticList ignored;  // the run reads the table too and reports its lines
    const double per = o.run.machine_units == "inch" ? 25.4 : 1.0;
    if (auto table = gcode::read_tool_table(*file, 0, per, ignored)) {
      for (const gcode::ToolEntry& t : table->entries()) {
        if (t.diameter <= 0.0) continue;
        auto tool = stock::tool_from_comment(t.comment, t.diameter);
        if (!tool) {
          return tl::unexpected(
              fmt::format("{}: tool {}'s comment: {}", o.run.tool_table, t.number, tool.error()));
        }
        tools[t.number] = *tool;
      }
    }
  }
  for (const std::string& spec : o.tool_shapes) {
    auto tool = stock::parse_tool_spec(spec, tools);
    if (!tool) return tl::unexpected(tool.error());
    tools[tool->first] = tool->second;
  }
  return tools;
}

// A tool as the report lists it: the words above its end only where given.
json tool_json(const stock::ToolVolume& t) {
  json j = {{"tool", t.tool}, {"shape", stock::shape_name(t.shape)}};
  if (t.shape.flutes > 0.0) j["flutes_mm"] = t.shape.flutes;
  if (t.shape.holder > 0.0) j["holder_mm"] = t.shape.holder;
  if (t.shape.stickout > 0.0) j["stickout_mm"] = t.shape.stickout;
  if (t.shape.plunge_ramp > 0.0) j["plunge_ramp_deg"] = t.shape.plunge_ramp;
  return j;
}

// mm³ a minute; null when nothing ran for a time.
json rate_json(double mm3, double seconds) {
  return seconds > 0.0 ? json(mm3 / seconds * 60.0) : json(nullptr);
}

json operations_json(const stock::StockSimulator& sim, const stock::RemovalTimeline& timeline) {
  json ops = json::array();
  for (std::size_t i = 0; i < sim.operations().size(); ++i) {
    const stock::Operation& op = sim.operations()[i];
    const double s = i < timeline.operation_s().size() ? timeline.operation_s()[i] : 0.0;
    ops.push_back({{"tool", op.tool},
                   {"lines", {op.first_line, op.last_line}},
                   {"removed_mm3", op.removed_mm3},
                   {"time_s", s},
                   {"mm3_per_min", rate_json(op.removed_mm3, s)}});
  }
  return ops;
}

// The removal rate over time (docs/simulate.md, "Removal rate").
json removal_rate_json(const stock::RemovalTimeline& t, double removed_mm3) {
  json bins = json::array();
  for (const double v : t.bins())
    bins.push_back(v / t.bin_s() * 60.0);
  const std::size_t peak = t.peak_bin();
  const bool cut = !t.bins().empty() && t.bins()[peak] > 0.0;
  return {{"bin_s", t.bin_s()},
          {"mm3_per_min", std::move(bins)},
          {"peak_mm3_per_min", cut ? json(t.bins()[peak] / t.bin_s() * 60.0) : json(nullptr)},
          {"peak_at_s", cut ? json(static_cast<double>(peak) * t.bin_s()) : json(nullptr)},
          {"cutting_s", t.cutting_s()},
          {"mean_cutting_mm3_per_min", rate_json(removed_mm3, t.cutting_s())}};
}

// "LAYER=Z": the layer's closed contours of the target drawing, as polygons.
tl::expected<stock::TargetLayer, std::string> read_target(const std::string& dxf,
                                                          const std::string& spec) {
  const std::size_t eq = spec.rfind('=');
  stock::TargetLayer t;
  if (eq == std::string::npos || eq == 0) {
    return tl::unexpected(fmt::format("--target '{}' is not LAYER=Z", spec));
  }
  t.layer = spec.substr(0, eq);
  const std::string z = spec.substr(eq + 1);
  const auto [end, ec] = std::from_chars(z.data(), z.data() + z.size(), t.z);
  if (z.empty() || ec != std::errc() || end != z.data() + z.size() || !std::isfinite(t.z) ||
      std::fabs(t.z) > kMaxTargetZ) {
    return tl::unexpected(
        fmt::format("--target '{}': Z must be a number of mm within ±{:g}", spec, kMaxTargetZ));
  }
  auto rings = closed_rings(dxf, t.layer, kTargetChord);
  if (!rings) return tl::unexpected(fmt::format("--target {}: {}", spec, rings.error()));
  t.rings = std::move(*rings);
  return t;
}

tl::expected<std::vector<stock::TargetLayer>, std::string> read_targets(const SimulateOptions& o) {
  std::vector<stock::TargetLayer> out;
  if (o.target_dxf.empty() != o.targets.empty()) {
    return tl::unexpected(
        std::string("--target-dxf FILE and --target LAYER=Z go together: the drawing, and the "
                    "depth of each of its layers to check"));
  }
  if (!std::isfinite(o.target_tolerance) || o.target_tolerance < 0.0 || o.target_tolerance > 10.0) {
    return tl::unexpected(std::string("--target-tolerance must be from 0 to 10 mm"));
  }
  for (const std::string& spec : o.targets) {
    auto t = read_target(o.target_dxf, spec);
    if (!t) return tl::unexpected(t.error());
    out.push_back(std::move(*t));
  }
  return out;
}

// Each layer's area against its depth; a warning for each that is not down to it.
std::vector<stock::TargetResult> check_targets(const stock::HeightMap& map,
                                               const std::vector<stock::TargetLayer>& targets,
                                               double tolerance) {
  std::vector<stock::TargetResult> results;
  for (const stock::TargetLayer& t : targets) {
    results.push_back(stock::check_target(map, t, tolerance));
    if (results.back().above_mm2 > 0.0) {
      fmt::print(stderr, "usina: warning[{}]: {}\n",
                 core::code_name(core::Code::MaterialAboveTarget),
                 stock::material_above_message(results.back(), tolerance));
    }
  }
  return results;
}

json targets_json(const std::vector<stock::TargetResult>& results) {
  json out = json::array();
  for (const stock::TargetResult& r : results) {
    json j = {{"layer", r.layer},
              {"z", r.z},
              {"title", r.title},
              {"area_mm2", r.area_mm2},
              {"above_mm2", r.above_mm2},
              {"left_mm3", r.left_mm3},
              {"most_above_mm", r.most_above_mm}};
    if (r.operation > 0) j["operation"] = r.operation;
    if (r.above_mm2 > 0.0) {
      j["most_at"] = {r.most_at.x, r.most_at.y};
      j["code"] = core::code_name(core::Code::MaterialAboveTarget);
    }
    out.push_back(std::move(j));
  }
  return out;
}

// What the run made: the stock, the simulator's figures, the times.
struct SimulateRun {
  const stock::HeightMap& map;
  const stock::StockSimulator& sim;
  const stock::RemovalTimeline& timeline;
  const sim::MachineProfile& machine;
  bool complete = false;
};

json report_json(const SimulateOptions& o, const SimulateRun& run,
                 const std::vector<stock::TargetResult>& targets) {
  const stock::HeightMap& map = run.map;
  const stock::StockSimulator& sim = run.sim;
  json per_tool = json::object();
  json tools = json::array();
  for (const stock::ToolVolume& t : sim.tools()) {
    per_tool[std::to_string(t.tool)] = {{"removed_mm3", t.removed_mm3}};
    tools.push_back(tool_json(t));
  }
  json checks = json::array();
  for (const stock::Check& c : sim.checks()) {
    checks.push_back(
        {{"code", core::code_name(c.code)}, {"line", c.loc.line}, {"message", c.message}});
  }
  const stock::StockBox& b = map.box();
  return {{"program", o.run.file},
          {"complete", run.complete},
          {"stock",
           {{"box", {b.width, b.length, b.height}},
            {"origin", {b.origin.x, b.origin.y, b.origin.z}},
            {"cells", {map.nx(), map.ny()}},
            {"cell_mm", {map.dx(), map.dy()}},
            {"volume_mm3", b.width * b.length * b.height}}},
          {"removed_mm3", sim.removed_mm3()},
          {"rapid_removed_mm3", sim.rapid_removed_mm3()},
          {"per_tool", std::move(per_tool)},
          {"per_operation", operations_json(sim, run.timeline)},
          {"machine",
           {{"name", run.machine.name},
            {"profile", o.machine.empty() ? json(nullptr) : json(o.machine)}}},
          {"time_s", run.timeline.total_s()},
          {"removal_rate", removal_rate_json(run.timeline, sim.removed_mm3())},
          {"tools", std::move(tools)},
          {"checks", std::move(checks)},
          {"targets", targets_json(targets)}};
}

bool ends_with(const std::string& s, std::string_view tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// Writes one output through OutputFile: a failed write leaves the old file.
int write_output(const std::string& path, const std::vector<std::string>& inputs,
                 const std::function<tl::expected<void, std::string>(std::FILE*)>& write) {
  auto out = core::OutputFile::open(path, inputs);
  if (!out) return fail(out.error());
  if (auto ok = write(out->stream()); !ok) return fail(fmt::format("{}: {}", path, ok.error()));
  if (auto ok = out->commit(); !ok) return fail(ok.error());
  return 0;
}

// `raster`: the module that writes the PNG pictures, when one is asked for.
int write_outputs(const SimulateOptions& o, const SimulateRun& run,
                  const std::vector<stock::TargetResult>& targets, const RasterWriters* raster,
                  const std::vector<std::string>& inputs) {
  const stock::HeightMap& map = run.map;
  const StockView view = o.view == "top" ? StockView::Top : StockView::Iso;
  for (const std::string& path : o.outputs) {
    int status = 0;
    if (ends_with(path, ".json")) {
      status = write_output(path, inputs, [&](std::FILE* f) -> tl::expected<void, std::string> {
        const std::string text = report_json(o, run, targets).dump(2) + "\n";
        std::fwrite(text.data(), 1, text.size(), f);
        return {};
      });
    } else if (ends_with(path, ".stl")) {
      status = write_output(path, inputs, [&](std::FILE* f) -> tl::expected<void, std::string> {
        core::FileOstream out(f);
        stock::write_stl(map, out);
        out.flush();
        return {};
      });
    } else {
      status = write_output(path, inputs,
                            [&](std::FILE* f) { return raster->write_stock_png(map, view, f); });
    }
    if (status != 0) return status;
  }
  if (!o.height_map.empty()) {
    return write_output(o.height_map, inputs, [&](std::FILE* f) -> tl::expected<void, std::string> {
      core::FileOstream out(f);
      stock::write_height_png(map, out);
      out.flush();
      return {};
    });
  }
  return 0;
}

void print_rate(const SimulateRun& run) {
  const stock::RemovalTimeline& t = run.timeline;
  fmt::print("time             {:.1f} s on {} (the planner's, with look-ahead)\n", t.total_s(),
             run.machine.name);
  const std::size_t peak = t.peak_bin();
  if (t.bins().empty() || !(t.bins()[peak] > 0.0) || !(t.cutting_s() > 0.0)) return;
  fmt::print(
      "removal rate     peak {:.1f} mm³/min at {:.1f} s (bins of {:g} s), {:.1f} mm³/min "
      "over {:.1f} s of cutting\n",
      t.bins()[peak] / t.bin_s() * 60.0, static_cast<double>(peak) * t.bin_s(), t.bin_s(),
      run.sim.removed_mm3() / t.cutting_s() * 60.0, t.cutting_s());
}

void print_summary(const SimulateRun& run) {
  const stock::HeightMap& map = run.map;
  const stock::StockSimulator& sim = run.sim;
  const stock::StockBox& b = map.box();
  fmt::print("stock            {:g} x {:g} x {:g} mm, {} x {} cells of {:g} x {:g} mm\n", b.width,
             b.length, b.height, map.nx(), map.ny(), map.dx(), map.dy());
  fmt::print("removed          {:.3f} mm³ ({:.2f} % of the stock)\n", sim.removed_mm3(),
             100.0 * sim.removed_mm3() / (b.width * b.length * b.height));
  for (const stock::ToolVolume& t : sim.tools()) {
    fmt::print("  T{:<5} {:>14.3f} mm³  {}\n", t.tool, t.removed_mm3, stock::shape_name(t.shape));
  }
  if (sim.operations().size() > 1) {
    const std::vector<double>& seconds = run.timeline.operation_s();
    for (std::size_t i = 0; i < sim.operations().size(); ++i) {
      const stock::Operation& op = sim.operations()[i];
      // A job's ops come from no program line.
      const std::string lines =
          op.first_line > 0 ? fmt::format("lines {}-{}", op.first_line, op.last_line) : "";
      fmt::print("  {} T{:<5} {:>10.3f} mm³ {:>9.1f} s\n", lines, op.tool, op.removed_mm3,
                 i < seconds.size() ? seconds[i] : 0.0);
    }
  }
  if (sim.rapid_removed_mm3() > 0.0) {
    fmt::print("  by rapids {:>11.3f} mm³\n", sim.rapid_removed_mm3());
  }
  print_rate(run);
  if (!sim.checks().empty())
    fmt::print("checks           {} (on standard error)\n", sim.checks().size());
}

void print_targets(const std::vector<stock::TargetResult>& results) {
  for (const stock::TargetResult& r : results) {
    fmt::print("target {} Z{:g}  {:.2f} mm², {:.2f} mm² above it (up to {:.3f} mm)\n", r.title, r.z,
               r.area_mm2, r.above_mm2, r.most_above_mm);
  }
}

// A job file given as the program: the job, and the steps its run took.
struct JobInput {
  core::SourceManager sources;
  std::optional<job::LoadedJob> loaded;
  job::SheetLog log;
};

// Reads the job when the program is one: 0, or the exit status of its errors.
int load_job_input(const SimulateOptions& o, Errors& errors, JobInput& in) {
  if (!is_job_file(o.run.file)) return 0;
  errors.set_sources(&in.sources);
  std::string io_error;
  in.loaded = job::load_job(o.run.file, in.sources, errors, io_error);
  if (!io_error.empty()) return fail(io_error);
  return in.loaded ? 0 : 1;
}

// The stock: --stock (and --origin), else the job's.
tl::expected<stock::StockBox, std::string> stock_box(const SimulateOptions& o, const JobInput& in) {
  tl::expected<stock::StockBox, std::string> box =
      tl::unexpected(std::string("--stock box:WxLxH is required (a job file gives its own)"));
  if (!o.stock.empty()) {
    box = stock::parse_stock(o.stock);
  } else if (in.loaded) {
    box = job_stock(in.loaded->job);
  }
  if (box && !o.origin.empty()) box->origin = {o.origin[0], o.origin[1], o.origin[2]};
  return box;
}

// The tools: the job library's, then the tool table's and --tool-shape over them.
tl::expected<std::map<int, stock::ToolShape>, std::string> all_tool_shapes(const SimulateOptions& o,
                                                                           const JobInput& in) {
  std::map<int, stock::ToolShape> tools;
  if (in.loaded) {
    auto shapes = job_tool_shapes(in.loaded->tools);
    if (!shapes) return tl::unexpected(fmt::format("{}: {}", in.loaded->job.tools, shapes.error()));
    tools = std::move(*shapes);
  }
  return tool_shapes(o, std::move(tools));
}

// Runs the program (or makes the job) into `sink`: the run's exit status.
int run_input(const SimulateOptions& o, JobInput& in, canon::Sink& sink, Errors& errors) {
  if (!in.loaded)
    return run_program(o.run, sink,
                       [&errors](const core::SourceManager& s) { errors.set_sources(&s); });
  const bool made = job::make_job(*in.loaded, sink, errors, &in.log);
  sink.finish();
  return made && errors.errors() == 0 ? 0 : 1;
}

// Every output checked before the run: what each is, and the raster module
// a picture needs (nullptr when none is asked for), or why not.
tl::expected<const RasterWriters*, std::string> output_writers(const SimulateOptions& o) {
  const RasterWriters* raster = nullptr;
  for (const std::string& path : o.outputs) {
    if (!ends_with(path, ".json") && !ends_with(path, ".stl") && !ends_with(path, ".png")) {
      return tl::unexpected(fmt::format(
          "cannot tell what to write to '{}': give OUT.png, OUT.stl or OUT.json", path));
    }
    if (ends_with(path, ".png") && raster == nullptr) {
      const auto writers = raster_writers();
      if (!writers) return tl::unexpected(fmt::format("simulate: {}", writers.error()));
      raster = *writers;
    }
  }
  return raster;
}

// The files the run read: no output may be written over them.
std::vector<std::string> never_written(const SimulateOptions& o, const JobInput& in) {
  std::vector<std::string> inputs = input_paths(o.run);
  if (!o.target_dxf.empty()) inputs.push_back(o.target_dxf);
  if (!o.machine.empty()) inputs.push_back(o.machine);
  if (in.loaded) {
    const job::Job& j = in.loaded->job;
    for (const std::string& f : {j.tools, j.materials, j.drawing, j.machine}) {
      if (!f.empty()) inputs.push_back(f);
    }
  }
  return inputs;
}

int simulate(const SimulateOptions& o) {
  Errors errors;
  JobInput in;
  if (const int loaded = load_job_input(o, errors, in); loaded != 0) return loaded;
  auto box = stock_box(o, in);
  if (!box) return fail(box.error());
  auto map = stock::HeightMap::make(*box, o.resolution);
  if (!map) {
    fmt::print(stderr, "usina: error[{}]: {}\n", core::code_name(core::Code::StockGridTooLarge),
               map.error());
    return kBadInput;
  }
  if (o.floor && !std::isfinite(*o.floor)) return fail("--floor must be a finite Z in mm");
  auto tools = all_tool_shapes(o, in);
  if (!tools) return fail(tools.error());
  // A picture needs the raster module: a missing one is said before the run.
  const auto raster = output_writers(o);
  if (!raster) return fail(raster.error());
  auto targets = read_targets(o);
  if (!targets) return fail(targets.error());
  // --machine, else the job's machine, else the generic mill.
  const auto machine = o.machine.empty() && in.loaded && in.loaded->machine
                           ? in.loaded->machine
                           : load_machine_profile(o.machine);
  if (!machine) return kBadInput;
  stock::SimulateOptions so;
  so.tools = std::move(*tools);
  so.floor = o.floor;
  stock::StockSimulator sim(*map, so, errors);
  // The times: stats' planner on the same stream; its checks are stats' business.
  stock::RemovalTimeline timeline;
  core::DiagnosticList timing_checks;
  sim::StatsSink timer(*machine, {}, timing_checks);
  sim.set_timeline(&timeline);
  timer.observe([&timeline](std::uint64_t op, double s) { timeline.timed(op, s); });
  canon::TeeSink both({&sim, &timer});
  const int status = run_input(o, in, both, errors);
  if (status == kBadInput) return status;
  timer.finish();
  timeline.finish();
  if (in.loaded) {
    auto job_targets_found = job_targets(*in.loaded, in.log);
    if (!job_targets_found) return fail(job_targets_found.error());
    targets->insert(targets->end(), job_targets_found->begin(), job_targets_found->end());
  }
  const SimulateRun run{*map, sim, timeline, *machine, status == 0};
  print_summary(run);
  const auto results = check_targets(*map, *targets, o.target_tolerance);
  print_targets(results);
  if (const int written = write_outputs(o, run, results, *raster, never_written(o, in));
      written != 0)
    return written;
  return status != 0 ? status : (errors.errors() > 0 ? 1 : 0);
}

}  // namespace

void add_simulate(CLI::App& app) {
  auto opts = std::make_shared<SimulateOptions>();
  CLI::App* cmd = app.add_subcommand(
      "simulate", "cut a stock with the program: volumes, checks, STL and pictures");
  add_run_options(*cmd, opts->run);
  cmd->add_option("--stock", opts->stock,
                  "the stock: box:WxLxH in mm, e.g. box:200x150x30 (required, unless the program "
                  "is a job file: then its stock)");
  cmd->add_option("--origin", opts->origin,
                  "X,Y,Z of the stock's corner at least X and Y on its top face (default 0,0,0)")
      ->delimiter(',')
      ->expected(3);
  cmd->add_option("--resolution", opts->resolution, "cell size of the height map, mm")
      ->capture_default_str();
  cmd->add_option("--tool-shape", opts->tool_shapes,
                  "T=SHAPE[/D][,WORD]...: flat, ball, bull:R, drill[:A], vee[:A]; flutes:L, "
                  "holder:D, stickout:L, no-plunge[:A] (docs/simulate.md)");
  cmd->add_option("--floor", opts->floor, "Z mm the tool may not cut below");
  cmd->add_option("-o,--output", opts->outputs,
                  "OUT.png (picture), OUT.stl (the stock), OUT.json (the report); repeatable");
  cmd->add_option("--target-dxf", opts->target_dxf,
                  "a drawing whose layers' closed contours must be cut down to a depth");
  cmd->add_option("--target", opts->targets,
                  "LAYER=Z: the depth of a layer of --target-dxf; stock left above it is "
                  "W_MATERIAL_ABOVE_TARGET; repeatable");
  cmd->add_option("--target-tolerance", opts->target_tolerance,
                  "mm the stock may stand above a target's depth")
      ->capture_default_str();
  cmd->add_option("--machine", opts->machine,
                  "machine profile for the times and the removal rate (TOML, as stats reads it); "
                  "without it a generic mill");
  cmd->add_option("--height-map", opts->height_map, "the heights as a 16-bit greyscale PNG");
  cmd->add_option("--view", opts->view, "the picture: iso or top")
      ->check(CLI::IsMember({"iso", "top"}))
      ->capture_default_str();
  cmd->callback([opts] { set_exit_status(simulate(*opts)); });
}

}  // namespace usina::cli
