// usina job JOB.toml --post P -o part.nc: a whole part from one job file
// (docs/job.md): its operations in order, each with its tool and its speeds
// and feeds, posted for one control.
//
// Exit status: 0; 1 when the job (or its tool library, materials, machine
// profile, drawing) has an error, reported at its line; 2 for a file that
// cannot be read or a bad option.
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <sstream>
#include <string>

#include <fmt/format.h>

#include "cli/post_output.hpp"
#include "cli/raster_module.hpp"
#include "cli/verbs.hpp"
#include "core/output_file.hpp"
#include "core/source.hpp"
#include "draw/builder.hpp"
#include "draw/layer_style.hpp"
#include "draw/svg_writer.hpp"
#include "job/load.hpp"
#include "job/make.hpp"
#include "job/sheet.hpp"

namespace usina::cli {
namespace {

enum class SheetFormat { Html, Pdf };

struct JobCli {
  std::string file;
  PostOutput output;
  std::string sheet;  // --sheet: the setup sheet's file, HTML or PDF by its extension
  SheetFormat sheet_format = SheetFormat::Html;
  const RasterWriters* raster = nullptr;  // the PDF's writer, loaded for a .pdf sheet
};

// The sheet's extension chooses its format; no other is guessed.
std::optional<SheetFormat> sheet_format_of(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".html" || ext == ".htm") return SheetFormat::Html;
  if (ext == ".pdf") return SheetFormat::Pdf;
  return std::nullopt;
}

// Before the job is read: the sheet's format, and for a PDF the raster
// module (a missing one is said at once, not after the program is made).
int check_sheet_option(JobCli& o) {
  const auto format = sheet_format_of(o.sheet);
  if (!format) {
    fmt::print(stderr,
               "usina: error: --sheet {}: the extension chooses the sheet's format: .html (or "
               ".htm) or .pdf\n",
               o.sheet);
    return 2;
  }
  o.sheet_format = *format;
  if (*format == SheetFormat::Pdf) {
    const auto writers = raster_writers();
    if (!writers) {
      fmt::print(stderr, "usina: error: {}\n", writers.error());
      return 2;
    }
    o.raster = *writers;
  }
  return 0;
}

// The stock's outline, in grey, beside the tool path.
void draw_stock(const job::Stock& s, draw::Drawing& d) {
  draw::Layer& layer = d.layer("STOCK");
  layer.style = {8, {150, 150, 150}, false};
  if (s.shape == "box") {
    const core::Vec2 a{s.origin[0], s.origin[1]};
    const core::Vec2 b{a.x + s.size[0], a.y + s.size[1]};
    layer.entities.push_back(draw::Polyline{{a, {b.x, a.y}, b, {a.x, b.y}}, true});
  } else {
    layer.entities.push_back(draw::Circle{{s.origin[0], s.origin[1]}, s.size[0] / 2});
  }
}

// --sheet and -o may not name one file (neither exists yet: no inode to compare).
bool same_path(const std::string& a, const std::string& b) {
  std::error_code ec1;
  std::error_code ec2;
  const auto ca = std::filesystem::weakly_canonical(a, ec1);
  const auto cb = std::filesystem::weakly_canonical(b, ec2);
  return ec1 || ec2 ? a == b : ca == cb;
}

// Each drill step's holes as circles of its drill's diameter.
void draw_holes(const job::SheetLog& log, draw::Drawing& d) {
  for (const job::SheetStep& s : log.steps) {
    for (const core::Vec2& c : s.holes)
      d.layer(draw::kHolesLayer).entities.push_back(draw::Circle{c, s.tool.diameter / 2});
  }
}

// The sheet into its file, put in place only when all of it was written.
draw::WriteResult write_sheet(const JobCli& o, const core::Document& doc,
                              const draw::Drawing& picture, core::OutputFile& file) {
  if (o.sheet_format == SheetFormat::Pdf) {
    const draw::WriteResult w = o.raster->write_sheet_pdf(doc, picture, file.stream());
    if (!w) return tl::unexpected(file.write_error().value_or(w.error()));
  } else {
    std::ostringstream svg;
    if (const draw::WriteResult w = draw::write_svg(picture, svg); !w) return w;
    // Inside the page the SVG element goes without its XML declaration.
    const std::string svg_text = svg.str();
    const std::size_t element = std::min(svg_text.find("<svg"), svg_text.size());
    const std::string html = job::document_html(doc, std::string_view(svg_text).substr(element));
    if (std::fwrite(html.data(), 1, html.size(), file.stream()) != html.size())
      return tl::unexpected(file.write_error().value_or("cannot write " + o.sheet));
  }
  return file.commit();
}

// The job made once into the post and, for the sheet, into the timer and
// the picture. The sheet's file is opened (and checked) before anything is
// written, and put in place after the program; a failed sheet leaves no
// file (its temporary goes with the OutputFile).
int run_with_sheet(const JobCli& o, const job::LoadedJob& loaded, core::SourceManager& sources,
                   DiagnosticPrinter& diags) {
  if (o.output.out != "-" && same_path(o.sheet, o.output.out)) {
    fmt::print(stderr, "usina: error: --sheet and -o name the same file, {}\n", o.sheet);
    return 2;
  }
  std::vector<std::string> not_these = o.output.inputs;
  if (o.output.out != "-") not_these.push_back(o.output.out);
  auto sheet_file = core::OutputFile::open(o.sheet, not_these);
  if (!sheet_file) {
    fmt::print(stderr, "usina: error: {}\n", sheet_file.error());
    return 2;
  }
  job::SheetLog log;
  const sim::MachineProfile machine = loaded.machine.value_or(sim::default_machine_profile());
  job::SheetTimer timer(machine, log);
  draw::Drawing picture;
  draw::DrawingBuilder builder(picture, draw::View::Toolpath);
  const int status = write_program(o.output, [&](canon::Sink& sink, PostDiagnostics& post_diags) {
    post_diags.set_sources(&sources);
    canon::TeeSink both({&sink, &timer, &builder});
    return job::make_job(loaded, both, diags, &log) && diags.errors() == 0 ? 0 : 1;
  });
  if (status != 0) return status;  // the sheet's temporary goes with sheet_file
  timer.finish();
  draw_stock(loaded.job.stock, picture);
  draw_holes(log, picture);
  const std::string program = o.output.out == "-" ? "(standard output)" : o.output.out;
  const core::Document doc = job::sheet_document(loaded, log, timer, program);
  if (auto w = write_sheet(o, doc, picture, *sheet_file); !w) {
    fmt::print(stderr, "usina: error: {}\n", w.error());
    return 2;
  }
  return 0;
}

int run_job(JobCli& o) {
  if (!o.sheet.empty()) {
    if (const int status = check_sheet_option(o); status != 0) return status;
  }
  core::SourceManager sources;
  DiagnosticPrinter diags;
  diags.set_sources(&sources);
  std::string io_error;
  const auto loaded = job::load_job(o.file, sources, diags, io_error);
  if (!io_error.empty()) {
    fmt::print(stderr, "usina: error: {}\n", io_error);
    return 2;
  }
  if (!loaded) return 1;
  // The output may be none of the files the job reads.
  o.output.inputs = {o.file, loaded->job.tools, loaded->job.materials};
  if (!loaded->job.drawing.empty()) o.output.inputs.push_back(loaded->job.drawing);
  if (!loaded->job.machine.empty()) o.output.inputs.push_back(loaded->job.machine);
  if (!o.sheet.empty()) return run_with_sheet(o, *loaded, sources, diags);
  return write_program(o.output, [&](canon::Sink& sink, PostDiagnostics& post_diags) {
    post_diags.set_sources(&sources);
    return job::make_job(*loaded, sink, diags) && diags.errors() == 0 ? 0 : 1;
  });
}

}  // namespace

void add_job(CLI::App& app) {
  auto o = std::make_shared<JobCli>();
  CLI::App* cmd = app.add_subcommand(
      "job", "a whole part from a job file: stock, material, tools, operations (docs/job.md)");
  cmd->add_option("JOB", o->file, "the job file (TOML)")->required();
  add_post_options(*cmd, o->output);
  cmd->add_option("--sheet", o->sheet,
                  "also write the setup sheet, HTML or PDF by its extension (.html, .pdf): "
                  "stock, zero, tools and stick-out, operations and times, cycle time and cost");
  cmd->callback([o] { set_exit_status(run_job(*o)); });
}

}  // namespace usina::cli
