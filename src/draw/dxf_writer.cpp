#include "draw/dxf_writer.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iterator>
#include <memory>
#include <string_view>

#include <dxflib/dl_dxf.h>
#include <fmt/format.h>

#include "core/units.hpp"
#include "draw/finite.hpp"

namespace usina::draw {
namespace {

// ISO DASHED (acadiso.lin): 12.7 mm dash, 6.35 mm gap, scaled by $LTSCALE.
constexpr std::array<double, 2> kDashedPattern{12.7, -6.35};
constexpr double kDashedLength = 19.05;
constexpr int kInsunitsMm = 4;
constexpr int kColorByLayer = 256;
constexpr int kDefaultLineweight = -3;

// dxflib's ASCII writer flushes its file after every real number: a
// write(2) a coordinate, 20 s for a million lines. This one writes the same
// group codes into a buffer that goes to the FILE 64 KiB at a time. The
// base opens /dev/null, which nothing is written to (its output functions
// are all overridden).
class BufferedWriter final : public DL_WriterA {
 public:
  explicit BufferedWriter(std::FILE* file)
      : DL_WriterA("/dev/null", DL_Codes::AC1015), file_(file) {}

  ~BufferedWriter() override = default;

  BufferedWriter(const BufferedWriter&) = delete;
  BufferedWriter& operator=(const BufferedWriter&) = delete;

  // Fixed point, trailing zeros cut but one decimal kept ("12.5", "3.0"),
  // as dxflib writes them (with 10 decimals instead of 16).
  void dxfReal(int gc, double value) const override {
    code(gc);
    const std::size_t start = buf_.size();
    fmt::format_to(std::back_inserter(buf_), "{:.10f}", value);
    std::size_t end = buf_.size();
    while (buf_[end - 1] == '0' && buf_[end - 2] != '.')
      --end;
    buf_.resize(end);
    if (std::string_view(buf_.data() + start, end - start) == "-0.0") {
      buf_.resize(start);
      buf_.append(std::string_view("0.0"));
    }
    line_end();
  }

  void dxfInt(int gc, int value) const override {
    code(gc);
    fmt::format_to(std::back_inserter(buf_), "{}\n", value);
  }

  void dxfHex(int gc, int value) const override {
    code(gc);
    fmt::format_to(std::back_inserter(buf_), "{:X}\n", value);
  }

  void dxfString(int gc, const char* value) const override {
    code(gc);
    buf_.append(std::string_view(value));
    line_end();
  }

  void dxfString(int gc, const std::string& value) const override {
    code(gc);
    buf_.append(value);
    line_end();
  }

  void flush() const {
    std::fwrite(buf_.data(), 1, buf_.size(), file_);
    buf_.clear();
  }

 private:
  // The group code right-aligned in three columns, as AutoCAD writes it.
  void code(int gc) const { fmt::format_to(std::back_inserter(buf_), "{:>3}\n", gc); }

  void line_end() const {
    buf_.push_back('\n');
    if (buf_.size() > (1u << 16)) flush();
  }

  std::FILE* file_;
  mutable fmt::memory_buffer buf_;
};

// Dashes about 1/40 of the drawing's larger side.
double linetype_scale(const Box& bounds) {
  const double size = std::max(bounds.width(), bounds.height());
  return std::clamp(size / (40.0 * kDashedLength), 0.01, 1000.0);
}

void write_header(DL_Dxf& dxf, DL_WriterA& dw, const Drawing& drawing) {
  dxf.writeHeader(dw);
  dw.dxfString(9, "$INSUNITS");
  dw.dxfInt(70, kInsunitsMm);
  dw.dxfString(9, "$MEASUREMENT");
  dw.dxfInt(70, 1);  // metric
  dw.dxfString(9, "$LTSCALE");
  dw.dxfReal(40, linetype_scale(drawing.bounds()));
  const Box box = finite_view_box(drawing);
  dw.dxfString(9, "$EXTMIN");
  dw.dxfReal(10, box.min.x);
  dw.dxfReal(20, box.min.y);
  dw.dxfReal(30, 0.0);
  dw.dxfString(9, "$EXTMAX");
  dw.dxfReal(10, box.max.x);
  dw.dxfReal(20, box.max.y);
  dw.dxfReal(30, 0.0);
  dw.sectionEnd();
}

void write_tables(DL_Dxf& dxf, DL_WriterA& dw, const std::vector<const Layer*>& layers) {
  dw.sectionTables();
  dxf.writeVPort(dw);
  std::array<double, 2> dashes = kDashedPattern;  // dxflib takes a non-const pointer
  dw.tableLinetypes(4);
  dxf.writeLinetype(dw, DL_LinetypeData("BYBLOCK", "", 0, 0, 0.0));
  dxf.writeLinetype(dw, DL_LinetypeData("BYLAYER", "", 0, 0, 0.0));
  dxf.writeLinetype(dw, DL_LinetypeData("CONTINUOUS", "Solid line", 0, 0, 0.0));
  dxf.writeLinetype(
      dw, DL_LinetypeData("DASHED", "Dashed __ __ __", 0, 2, kDashedLength, dashes.data()));
  dw.tableEnd();
  dw.tableLayers(static_cast<int>(layers.size()) + 1);
  dxf.writeLayer(dw, DL_LayerData("0", 0),
                 DL_Attributes("", 7, kDefaultLineweight, "CONTINUOUS", 1.0));
  for (const Layer* l : layers)
    dxf.writeLayer(dw, DL_LayerData(l->name, 0),
                   DL_Attributes("", l->style.aci, kDefaultLineweight,
                                 l->style.dashed ? "DASHED" : "CONTINUOUS", 1.0));
  dw.tableEnd();
  dw.tableStyle(1);
  dxf.writeStyle(dw, DL_StyleData("Standard", 0, 0.0, 1.0, 0.0, 0, 2.5, "txt", ""));
  dw.tableEnd();
  dxf.writeView(dw);
  dxf.writeUcs(dw);
  dw.tableAppid(1);
  dxf.writeAppid(dw, "ACAD");
  dw.tableEnd();
  dxf.writeDimStyle(dw, 2.5, 0.625, 0.625, 0.625, 2.5);
  dxf.writeBlockRecord(dw);
  dw.tableEnd();
  dw.sectionEnd();
}

void write_blocks(DL_Dxf& dxf, DL_WriterA& dw) {
  dw.sectionBlocks();
  for (const char* name : {"*Model_Space", "*Paper_Space", "*Paper_Space0"}) {
    dxf.writeBlock(dw, DL_BlockData(name, 0, 0.0, 0.0, 0.0));
    dxf.writeEndBlock(dw, name);
  }
  dw.sectionEnd();
}

class DxfEntities {
 public:
  DxfEntities(DL_Dxf& dxf, DL_WriterA& dw, const std::string& layer)
      : dxf_(dxf), dw_(dw), attr_(layer, kColorByLayer, kDefaultLineweight, "BYLAYER", 1.0) {}

  void operator()(const Line& l) {
    dxf_.writeLine(dw_, DL_LineData(l.from.x, l.from.y, 0.0, l.to.x, l.to.y, 0.0), attr_);
  }

  // DXF arcs run counter-clockwise from the start angle to the end angle,
  // in degrees: a clockwise arc is written from its end to its start.
  void operator()(const Arc& a) {
    const double from = a.ccw ? a.start_angle : a.end_angle;
    const double to = a.ccw ? a.end_angle : a.start_angle;
    dxf_.writeArc(
        dw_, DL_ArcData(a.center.x, a.center.y, 0.0, a.radius, degrees(from), degrees(to)), attr_);
  }

  void operator()(const Circle& c) {
    dxf_.writeCircle(dw_, DL_CircleData(c.center.x, c.center.y, 0.0, c.radius), attr_);
  }

  void operator()(const Polyline& p) {
    dxf_.writePolyline(
        dw_, DL_PolylineData(static_cast<int>(p.points.size()), 0, 0, p.closed ? 1 : 0), attr_);
    for (const Vec2& v : p.points)
      dxf_.writeVertex(dw_, DL_VertexData(v.x, v.y, 0.0, 0.0));
    dxf_.writePolylineEnd(dw_);
  }

 private:
  // In [0, 360).
  static double degrees(double rad) {
    double d = core::rad_to_deg(rad);
    if (d < 0.0) d += 360.0;
    return d >= 360.0 ? d - 360.0 : d;
  }

  DL_Dxf& dxf_;
  DL_WriterA& dw_;
  DL_Attributes attr_;
};

}  // namespace

WriteResult write_dxf(const Drawing& drawing, std::FILE* file) {
  DL_Dxf dxf;
  // DL_Dxf::out() would open the file with dxflib's slow writer; it is
  // called on /dev/null only to set the DXF version the DL_Dxf writes.
  const std::unique_ptr<DL_WriterA> version_only(dxf.out("/dev/null", DL_Codes::AC1015));
  auto dw = std::make_unique<BufferedWriter>(file);
  const std::vector<const Layer*> layers = drawing.layers();
  write_header(dxf, *dw, drawing);
  write_tables(dxf, *dw, layers);
  write_blocks(dxf, *dw);
  dw->sectionEntities();
  for (const Layer* l : layers) {
    DxfEntities entities(dxf, *dw, l->name);
    for (const Entity& e : l->entities)
      if (is_finite(e)) std::visit(entities, e);
  }
  dw->sectionEnd();
  dxf.writeObjects(*dw);
  dxf.writeObjectsEnd(*dw);
  dw->dxfEOF();
  dw->flush();
  dw->close();
  if (auto error = drawing.read_error()) return tl::unexpected(*error);
  return {};
}

WriteResult write_dxf_file(const Drawing& drawing, const std::string& path,
                           const std::vector<std::string>& inputs) {
  return write_to_file(path, inputs, [&](std::FILE* file) { return write_dxf(drawing, file); });
}

}  // namespace usina::draw
