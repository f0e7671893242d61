// usina draw FILE -o OUT.{dxf,svg,png,pdf}: a program as a drawing
// (docs/draw.md). The format is the output's extension. A program with an
// error is drawn up to the error and the command exits 1; bad options, an
// unreadable program or an unwritable output exit 2.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "cli/raster_module.hpp"
#include "cli/run.hpp"
#include "cli/verbs.hpp"
#include "core/file_ostream.hpp"
#include "core/output_file.hpp"
#include "draw/builder.hpp"
#include "draw/drawing.hpp"
#include "draw/dxf_writer.hpp"
#include "draw/raster_writer.hpp"
#include "draw/svg_writer.hpp"

namespace usina::cli {
namespace {

constexpr int kBadInput = 2;
// mm: the chordal tolerance the drawing gives arcs out of the XY plane; a
// run of moves closer than this to one line is drawn as that line.
constexpr double kDefaultTolerance = draw::DrawingBuilder::kArcTolerance;
// mm: more would draw a shape other than the program's.
constexpr double kMaxTolerance = 1.0;
// A4's long side at 600 dpi: the dots a printed PDF has at the most.
constexpr int kPdfDots = 7016;

enum class Format { Dxf, Svg, Png, Pdf };

struct DrawOptions {
  RunOptions run;
  std::string output;
  std::string format;  // empty: from the output's extension
  std::string view = "part";
  std::string start;
  std::string size;
  double tolerance = kDefaultTolerance;
};

int fail(std::string_view message) {
  fmt::print(stderr, "usina: error: draw: {}\n", message);
  return kBadInput;
}

std::optional<Format> format_named(std::string ext) {
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == "dxf") return Format::Dxf;
  if (ext == "svg") return Format::Svg;
  if (ext == "png") return Format::Png;
  if (ext == "pdf") return Format::Pdf;
  return std::nullopt;
}

std::optional<Format> format_of(const std::string& path) {
  const std::size_t dot = path.rfind('.');
  const std::size_t slash = path.rfind('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return std::nullopt;
  return format_named(path.substr(dot + 1));
}

// Numbers separated by `sep`; nullopt when any is not a finite number.
std::optional<std::vector<double>> numbers(std::string_view text, char sep) {
  std::vector<double> out;
  while (true) {
    const std::size_t end = std::min(text.find(sep), text.size());
    const std::string_view item = text.substr(0, end);
    double v = 0.0;
    const auto [p, ec] = std::from_chars(item.data(), item.data() + item.size(), v);
    if (item.empty() || ec != std::errc() || p != item.data() + item.size() || !std::isfinite(v))
      return std::nullopt;
    out.push_back(v);
    if (end == text.size()) return out;
    text.remove_prefix(end + 1);
  }
}

// "X,Y,Z" or "X,Y" (Z 0), mm.
std::optional<core::Vec3> parse_start(const std::string& text) {
  const auto v = numbers(text, ',');
  if (!v || v->size() < 2 || v->size() > 3) return std::nullopt;
  return core::Vec3{(*v)[0], (*v)[1], v->size() == 3 ? (*v)[2] : 0.0};
}

// "WIDTHxHEIGHT" in whole pixels within the PNG limit.
std::optional<draw::PixelSize> parse_size(const std::string& text) {
  const auto v = numbers(text, 'x');
  if (!v || v->size() != 2) return std::nullopt;
  const double w = (*v)[0];
  const double h = (*v)[1];
  if (w < 1 || h < 1 || w != std::floor(w) || h != std::floor(h) ||
      w * h > static_cast<double>(draw::kMaxPngPixels))
    return std::nullopt;
  return draw::PixelSize{static_cast<int>(w), static_cast<int>(h)};
}

// PNG and PDF come from the raster module (cli/raster_module.hpp), loaded
// only when such a picture is asked for; nullptr for DXF and SVG.
draw::WriteResult write_stream(const draw::Drawing& drawing, Format format, std::FILE* file,
                               draw::PixelSize size, const RasterWriters* raster) {
  switch (format) {
  case Format::Dxf: return draw::write_dxf(drawing, file);
  case Format::Svg: {
    core::FileOstream out(file);
    const draw::WriteResult written = draw::write_svg(drawing, out);
    out.flush();
    return written;
  }
  case Format::Png: return raster->write_png(drawing, file, size);
  case Format::Pdf: return raster->write_pdf(drawing, file);
  }
  return tl::unexpected(std::string("unknown format"));
}

// Runs the program into `drawing`; says when the drawing was full. The
// builder's retrace window (4 MB) is gone before the picture is made, so the
// two never add up (a PNG's image is 7.7 MB).
int build(const RunOptions& run, draw::View view, draw::Drawing& drawing) {
  draw::DrawingBuilder builder(drawing, view, run.start);
  const int status = run_program(run, builder);
  if (status == kBadInput) return status;
  builder.finish();
  if (auto note = builder.limit_note("usina trace lists them"))
    fmt::print(stderr, "usina: warning: {}\n", *note);
  return status;
}

// `-o -` is standard output (main checks that it was written).
draw::WriteResult write(const draw::Drawing& drawing, Format format, const std::string& path,
                        draw::PixelSize size, const std::vector<std::string>& inputs,
                        const RasterWriters* raster) {
  if (path == "-") return write_stream(drawing, format, stdout, size, raster);
  switch (format) {
  case Format::Dxf: return draw::write_dxf_file(drawing, path, inputs);
  case Format::Svg: return draw::write_svg_file(drawing, path, inputs);
  case Format::Png:
  case Format::Pdf:
    return draw::write_to_file(path, inputs, [&](std::FILE* file) {
      return write_stream(drawing, format, file, size, raster);
    });
  }
  return tl::unexpected(std::string("unknown format"));
}

int draw_program(DrawOptions& o) {
  const auto format = o.format.empty() ? format_of(o.output) : format_named(o.format);
  if (!format)
    return fail(
        fmt::format("cannot tell the format of '{}': its extension must be .dxf, .svg, "
                    ".png or .pdf, or give --format",
                    o.output));
  if (!o.start.empty()) {
    const auto start = parse_start(o.start);
    if (!start) return fail(fmt::format("--start '{}' is not X,Y,Z (mm)", o.start));
    o.run.start = *start;
  }
  draw::PixelSize size;
  if (!o.size.empty()) {
    if (*format != Format::Png) return fail("--size applies to PNG output only");
    const auto s = parse_size(o.size);
    if (!s)
      return fail(fmt::format("--size '{}' is not WIDTHxHEIGHT in pixels (at most {} pixels)",
                              o.size, draw::kMaxPngPixels));
    size = *s;
  }
  if (!std::isfinite(o.tolerance) || o.tolerance < 0.0 || o.tolerance > kMaxTolerance)
    return fail(
        fmt::format("--tolerance {} is not a length from 0 to {} mm", o.tolerance, kMaxTolerance));
  const draw::View view = o.view == "toolpath" ? draw::View::Toolpath : draw::View::Part;
  // The part view shows the programmed contour, not the compensated tool centre.
  o.run.ignore_cutter_comp = view == draw::View::Part;
  // Refused before the program runs: nothing is read into a file being written.
  const std::vector<std::string> inputs = input_paths(o.run);
  for (const std::string& input : inputs)
    if (auto ok = core::check_not_input(o.output, input); !ok) return fail(ok.error());
  // Loaded before the program runs: a missing module is said at once.
  const RasterWriters* raster = nullptr;
  if (*format == Format::Png || *format == Format::Pdf) {
    const auto writers = raster_writers();
    if (!writers) return fail(writers.error());
    raster = *writers;
  }
  draw::Drawing drawing;
  drawing.set_tolerance(o.tolerance);
  // A picture shows nothing finer than half its pixel: the memory and time of
  // a long program grow with what the picture can show, not with its moves.
  if (*format == Format::Png) drawing.set_picture(size.width, size.height);
  if (*format == Format::Pdf) drawing.set_picture(kPdfDots, kPdfDots);
  const int status = build(o.run, view, drawing);
  if (status == kBadInput) return status;
  // What was drawn before an error is written all the same.
  if (auto written = write(drawing, *format, o.output, size, inputs, raster); !written)
    return fail(written.error());
  return status;
}

}  // namespace

void add_draw(CLI::App& app) {
  auto opts = std::make_shared<DrawOptions>();
  CLI::App* cmd = app.add_subcommand("draw", "draw a program as DXF, SVG, PNG or PDF");
  add_run_options(*cmd, opts->run);
  cmd->add_option("-o,--output", opts->output,
                  "the drawing: OUT.dxf, OUT.svg, OUT.png or OUT.pdf ('-': standard output)")
      ->required();
  cmd->add_option("--format", opts->format,
                  "dxf, svg, png or pdf (default: the output's extension)")
      ->check(CLI::IsMember({"dxf", "svg", "png", "pdf"}));
  cmd->add_option("--view", opts->view,
                  "part: the programmed contour, holes and pockets; toolpath: every move by tool")
      ->check(CLI::IsMember({"part", "toolpath"}))
      ->capture_default_str();
  cmd->add_option("--start", opts->start, "where the tool starts, X,Y,Z in mm (default 0,0,0)");
  cmd->add_option("--tolerance", opts->tolerance,
                  "how far a drawn line may pass from the points of the moves it stands for, mm; "
                  "0 keeps every bend (PNG and PDF: at least half a pixel)")
      ->capture_default_str();
  cmd->add_option("--size", opts->size, "PNG size in pixels, WIDTHxHEIGHT (default 1600x1200)");
  cmd->callback([opts] { set_exit_status(draw_program(*opts)); });
}

}  // namespace usina::cli
