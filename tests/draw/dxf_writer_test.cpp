// The DXF writer, read back with dxflib's own reader: the header's units,
// the DASHED linetype, the layers with colours and linetypes, the entities
// with their coordinates (clockwise arcs written from their end).
#include "draw/dxf_writer.hpp"

#include <unistd.h>

#include <fstream>
#include <map>
#include <numbers>
#include <sstream>

#include <dxflib/dl_creationadapter.h>
#include <dxflib/dl_dxf.h>
#include <gtest/gtest.h>

#include "draw/layer_style.hpp"

namespace usina::draw {
namespace {

constexpr double kPi = std::numbers::pi;

struct ReadLayer {
  int color = 0;
  std::string linetype;
};

// Everything the reader reports, by kind.
class Collector final : public DL_CreationAdapter {
 public:
  void setVariableInt(const std::string& key, int value, int) override { ints[key] = value; }

  void addLinetype(const DL_LinetypeData& d) override { linetypes[d.name] = d.numberOfDashes; }

  void addLayer(const DL_LayerData& d) override {
    layers[d.name] = {attributes.getColor(), attributes.getLinetype()};
  }

  void addLine(const DL_LineData& d) override { lines.push_back({d, layer()}); }

  void addArc(const DL_ArcData& d) override { arcs.push_back({d, layer()}); }

  void addCircle(const DL_CircleData& d) override { circles.push_back({d, layer()}); }

  void addPolyline(const DL_PolylineData& d) override { polylines.push_back(d.number); }

  void addVertex(const DL_VertexData& d) override { vertices.push_back({d.x, d.y}); }

  std::string layer() const { return attributes.getLayer(); }

  std::map<std::string, int> ints;
  std::map<std::string, int> linetypes;
  std::map<std::string, ReadLayer> layers;
  std::vector<std::pair<DL_LineData, std::string>> lines;
  std::vector<std::pair<DL_ArcData, std::string>> arcs;
  std::vector<std::pair<DL_CircleData, std::string>> circles;
  std::vector<unsigned int> polylines;
  std::vector<Vec2> vertices;
};

// Writes `d` to a temporary file, reads it back.
Collector round_trip(const Drawing& d, std::string* text = nullptr) {
  char name[] = "/tmp/usina_dxf_test_XXXXXX";
  const int fd = mkstemp(name);
  EXPECT_GE(fd, 0);
  close(fd);
  EXPECT_TRUE(write_dxf_file(d, name));
  Collector c;
  DL_Dxf dxf;
  EXPECT_TRUE(dxf.in(name, &c));
  if (text != nullptr) {
    std::ifstream in(name);
    std::stringstream ss;
    ss << in.rdbuf();
    *text = ss.str();
  }
  unlink(name);
  return c;
}

Drawing sample() {
  Drawing d;
  Layer& contour = d.layer(kContourLayer);
  d.add_line(contour, {0, 0}, {40, 0});
  d.add_arc(contour, {{34, 6}, 6, -kPi / 2, 0, true});  // ccw from 270° to 0°
  d.add_arc(contour, {{0, 0}, 10, kPi / 2, 0, false});  // cw from 90° to 0°
  d.add_line(d.layer(kRapidLayer), {0, 0}, {0, -3});
  d.add_circle(d.layer(kHolesLayer), {{12, 15}, 3});
  d.add_circle(d.layer(kHolesLayer), {{28, 15}, 3});
  d.layer(kPocketsLayer);
  d.add_polyline(d.layer(toolpath_layer(2)), {{0, 0}, {1, 1}, {2, 0}});
  return d;
}

TEST(DxfWriter, HeaderSaysMillimetres) {
  EXPECT_EQ(round_trip(sample()).ints["$INSUNITS"], 4);
}

TEST(DxfWriter, IsAutoCad2000WithADashedLinetype) {
  std::string text;
  const Collector c = round_trip(sample(), &text);
  EXPECT_NE(text.find("AC1015"), std::string::npos);
  ASSERT_TRUE(c.linetypes.count("DASHED"));
  EXPECT_EQ(c.linetypes.at("DASHED"), 2);
}

TEST(DxfWriter, LayersHaveTheirColoursAndLinetypes) {
  const Collector c = round_trip(sample());
  for (const char* name : {"0", "CONTOUR", "RAPID", "HOLES", "POCKETS", "TOOLPATH_T2"})
    EXPECT_TRUE(c.layers.count(name)) << name;
  EXPECT_EQ(c.layers.at("RAPID").linetype, "DASHED");
  EXPECT_EQ(c.layers.at("RAPID").color, style_of(kRapidLayer).aci);
  EXPECT_EQ(c.layers.at("CONTOUR").linetype, "CONTINUOUS");
  EXPECT_EQ(c.layers.at("HOLES").color, 3);
  EXPECT_EQ(c.layers.at("TOOLPATH_T2").color, style_of(toolpath_layer(2)).aci);
}

TEST(DxfWriter, EntitiesComeBackWithTheirCoordinates) {
  const Collector c = round_trip(sample());
  ASSERT_EQ(c.lines.size(), 2u);
  EXPECT_EQ(c.lines[0].second, "CONTOUR");
  EXPECT_DOUBLE_EQ(c.lines[0].first.x2, 40.0);
  EXPECT_EQ(c.lines[1].second, "RAPID");
  EXPECT_DOUBLE_EQ(c.lines[1].first.y2, -3.0);
  ASSERT_EQ(c.circles.size(), 2u);
  EXPECT_EQ(c.circles[1].second, "HOLES");
  EXPECT_DOUBLE_EQ(c.circles[1].first.cx, 28.0);
  EXPECT_DOUBLE_EQ(c.circles[1].first.radius, 3.0);
  ASSERT_EQ(c.polylines.size(), 1u);
  EXPECT_EQ(c.polylines[0], 3u);
  ASSERT_EQ(c.vertices.size(), 3u);
  EXPECT_DOUBLE_EQ(c.vertices[1].y, 1.0);
}

TEST(DxfWriter, ArcsRunCounterClockwiseInDegrees) {
  const Collector c = round_trip(sample());
  ASSERT_EQ(c.arcs.size(), 2u);
  const DL_ArcData& ccw = c.arcs[0].first;
  EXPECT_DOUBLE_EQ(ccw.cx, 34.0);
  EXPECT_DOUBLE_EQ(ccw.radius, 6.0);
  EXPECT_NEAR(ccw.angle1, 270.0, 1e-9);
  EXPECT_NEAR(ccw.angle2, 0.0, 1e-9);
  // The clockwise arc from 90° to 0° is the counter-clockwise one from 0° to 90°.
  const DL_ArcData& cw = c.arcs[1].first;
  EXPECT_NEAR(cw.angle1, 0.0, 1e-9);
  EXPECT_NEAR(cw.angle2, 90.0, 1e-9);
}

TEST(DxfWriter, EmptyDrawingIsAValidFile) {
  Drawing d;
  d.layer(kContourLayer);
  const Collector c = round_trip(d);
  EXPECT_TRUE(c.layers.count("CONTOUR"));
  EXPECT_TRUE(c.lines.empty());
  EXPECT_EQ(c.ints.at("$INSUNITS"), 4);
}

TEST(DxfWriter, UnwritablePathIsAnError) {
  const auto r = write_dxf_file(Drawing{}, "/nonexistent/usina/x.dxf");
  ASSERT_FALSE(r);
  EXPECT_FALSE(r.error().empty());
}

}  // namespace
}  // namespace usina::draw
