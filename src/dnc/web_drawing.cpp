// The drawing of a revision (web_drawing.hpp): one run into the
// DrawingBuilder, written as SVG or DXF into memory.
#include "dnc/web_drawing.hpp"

#include <cstdio>
#include <memory>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <tl/expected.hpp>

#include "canon/sink.hpp"
#include "core/diagnostic.hpp"
#include "core/source.hpp"
#include "draw/drawing.hpp"
#include "draw/dxf_writer.hpp"
#include "draw/svg_writer.hpp"
#include "gcode/dialect.hpp"

namespace usina::dnc {
namespace {

// Where the page's reader sees the moves a full drawing leaves out: on the
// same page, not at a command line.
constexpr std::string_view kWebNotDrawn = "the 3D viewer shows every move";

// The first error of the run, for the note (the check lists them all).
class FirstError final : public core::DiagnosticSink {
 public:
  void report(core::Diagnostic d) override {
    if (d.severity != core::Severity::Error || first_) return;
    first_ = std::move(d);
  }

  const std::optional<core::Diagnostic>& first() const { return first_; }

 private:
  std::optional<core::Diagnostic> first_;
};

tl::expected<std::string, std::string> svg_text(const draw::Drawing& drawing) {
  std::ostringstream out;
  if (const draw::WriteResult written = draw::write_svg(drawing, out); !written)
    return tl::unexpected(written.error());
  return std::move(out).str();
}

// dxflib writes to a FILE: a memory stream (POSIX) holds it.
tl::expected<std::string, std::string> dxf_text(const draw::Drawing& drawing) {
  char* data = nullptr;
  std::size_t size = 0;
  std::FILE* file = open_memstream(&data, &size);
  if (file == nullptr) return tl::unexpected(std::string("no memory for the DXF"));
  const draw::WriteResult written = draw::write_dxf(drawing, file);
  const bool closed = std::fclose(file) == 0;
  const std::unique_ptr<char, decltype(&std::free)> owned(data, &std::free);
  if (!written) return tl::unexpected(written.error());
  if (!closed) return tl::unexpected(std::string("the DXF could not be written in memory"));
  return std::string(data, size);
}

std::string stop_of(const core::Diagnostic& d) {
  return fmt::format("the program stops at line {} ({}: {})", d.loc.line, core::code_name(d.code),
                     d.message);
}

// The run into `builder`; the first error, if the run stopped on one.
std::optional<core::Diagnostic> run_into(draw::DrawingBuilder& builder,
                                         const gcode::Dialect& dialect, std::string_view text,
                                         const DrawingSettings& settings) {
  FirstError diags;
  core::SourceManager sources;
  const std::uint32_t id =
      sources.add(core::SourceFile::from_string("<revision>", std::string(text)));
  gcode::InterpOptions options;
  // The part view shows the programmed contour, not the compensated tool centre (usina draw).
  options.ignore_cutter_comp = settings.view == draw::View::Part;
  canon::OpBudget budget(builder, settings.max_ops, diags);
  auto runner = dialect.make_runner(gcode::RunContext{
      sources, std::move(options), gcode::default_options(dialect), budget, diags});
  runner->run(id);
  budget.finish();
  return diags.first();
}

DrawingAnswer refused(unsigned status, std::string why) {
  DrawingAnswer a;
  a.status = status;
  a.complete = false;
  a.note = std::move(why);
  return a;
}

}  // namespace

DrawingAnswer program_drawing(std::string_view text, const DrawingSettings& settings) {
  const gcode::Dialect* dialect = gcode::find_dialect(settings.dialect);
  if (dialect == nullptr)
    return refused(422, fmt::format("the dialect {} is not one usina reads", settings.dialect));
  draw::Drawing drawing;
  drawing.set_tolerance(draw::DrawingBuilder::kArcTolerance);
  if (settings.format == DrawingFormat::Svg)
    drawing.set_picture(settings.picture_pixels, settings.picture_pixels);
  draw::DrawLimits limits;
  limits.max_entities = settings.max_entities;
  limits.max_polyline_points = settings.max_entities * 4;
  draw::DrawingBuilder builder(drawing, settings.view, {}, limits);
  const std::optional<core::Diagnostic> error = run_into(builder, *dialect, text, settings);
  if (error && drawing.entity_count() == 0)
    return refused(422, "nothing to draw: " + stop_of(*error) + " before its first move");
  DrawingAnswer a;
  if (error) {
    a.complete = false;
    a.note = stop_of(*error) + "; the drawing shows what ran before";
  } else if (auto full = builder.limit_note(kWebNotDrawn)) {
    a.complete = false;
    a.note = *full;
  }
  auto body = settings.format == DrawingFormat::Svg ? svg_text(drawing) : dxf_text(drawing);
  if (!body) return refused(500, body.error());
  a.body = std::move(*body);
  if (a.body.size() > settings.max_bytes) {
    // Said to the page and to a script alike: where to see it instead, both ways.
    return refused(413, fmt::format("the drawing is {} bytes, more than the {} the server sends: "
                                    "the 3D viewer shows every move, and `usina draw` on the "
                                    "program's file draws all of it",
                                    a.body.size(), settings.max_bytes));
  }
  return a;
}

// A JSON line (status, complete, note), then the body.
std::string encode_drawing_answer(const DrawingAnswer& answer) {
  const nlohmann::json head = {
      {"status", answer.status}, {"complete", answer.complete}, {"note", answer.note}};
  std::string out = head.dump(-1, ' ', true, nlohmann::json::error_handler_t::replace);
  out += '\n';
  out += answer.body;
  return out;
}

std::optional<DrawingAnswer> decode_drawing_answer(std::string_view bytes) {
  const std::size_t end = bytes.find('\n');
  if (end == std::string_view::npos) return std::nullopt;
  const auto head = nlohmann::json::parse(bytes.substr(0, end), nullptr, false);
  if (!head.is_object() || !head.contains("status") || !head["status"].is_number_unsigned())
    return std::nullopt;
  DrawingAnswer a;
  a.status = head["status"].get<unsigned>();
  a.complete = head.value("complete", false);
  a.note = head.value("note", "");
  a.body = std::string(bytes.substr(end + 1));
  return a;
}

}  // namespace usina::dnc
