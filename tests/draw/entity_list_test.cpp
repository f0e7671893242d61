#include "draw/entity_list.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "draw/drawing.hpp"
#include "draw/dxf_writer.hpp"
#include "draw/layer_style.hpp"
#include "draw/raster_writer.hpp"
#include "draw/svg_writer.hpp"

namespace usina::draw {
namespace {

namespace fs = std::filesystem;

// Every kind of entity the file form has, a polyline longer than a read
// piece (64 KiB) among them.
std::vector<Entity> every_kind(int copies) {
  std::vector<Entity> out;
  for (int i = 0; i < copies; ++i) {
    const double k = i;
    out.emplace_back(Line{{k, -k}, {k + 0.5, 1e-300}});
    out.emplace_back(Arc{{k, 2}, 3.25, -1.0, 2.5, true});
    out.emplace_back(Arc{{-k, 2}, 0.125, 3.0, -3.0, false});
    out.emplace_back(Circle{{1e6, -k}, 7.0});
    out.emplace_back(Polyline{{{0, 0}, {k, 1}, {2, k}}, false});
    out.emplace_back(Polyline{{{0, 0}, {1, 1}, {2, -k}}, true});
  }
  std::vector<Vec2> long_run;
  for (int i = 0; i < 10'000; ++i)
    long_run.push_back({std::cos(i * 0.01), i * 0.5});
  out.emplace_back(Polyline{long_run, false});
  out.emplace_back(Line{{-1, -2}, {-3, -4}});
  return out;
}

EntityList filled(const std::vector<Entity>& entities, std::size_t hold,
                  const std::string& folder = {}) {
  EntityList list(hold, folder);
  for (const Entity& e : entities)
    list.push_back(e);
  return list;
}

// A fresh folder of this test's own, removed with what is left in it.
struct Folder {
  Folder() {
    std::string name = (fs::temp_directory_path() / "usina-entity-list-XXXXXX").string();
    path = ::mkdtemp(name.data());
  }

  ~Folder() { fs::remove_all(path); }

  std::string path;
};

// This process's descriptors of unnamed files in `folder` (deleted files
// there, /proc says).
std::vector<int> descriptors_in(const std::string& folder) {
  std::vector<int> out;
  for (const auto& entry : fs::directory_iterator("/proc/self/fd")) {
    std::error_code ec;
    const std::string target = fs::read_symlink(entry.path(), ec).string();
    if (!ec && target.rfind(folder + "/", 0) == 0)
      out.push_back(std::stoi(entry.path().filename()));
  }
  return out;
}

int descriptor_in(const std::string& folder) {
  const auto fds = descriptors_in(folder);
  return fds.size() == 1 ? fds[0] : -1;
}

TEST(EntityList, WhatWentToTheFileComesBackWholeAndInOrder) {
  const auto entities = every_kind(500);
  const EntityList list = filled(entities, 1000);
  EXPECT_GT(list.spilled(), entities.size() / 2);
  EXPECT_EQ(list.size(), entities.size());
  EXPECT_EQ(list.to_vector(), entities);
  EXPECT_EQ(filled(every_kind(5), std::size_t{1} << 20).spilled(), 0u);
}

TEST(EntityList, TheLastEntityStaysInMemoryToBeLengthened) {
  EntityList list(100);
  for (int i = 0; i < 50; ++i)
    list.push_back(Line{{0, 0}, {1.0 * i, 0}});
  EXPECT_EQ(list.spilled(), 49u);
  std::get<Line>(list.back()).to = {99, 0};
  const auto read = list.to_vector();
  EXPECT_EQ(std::get<Line>(read.back()).to, (Vec2{99, 0}));
  EXPECT_EQ(std::get<Line>(read[48]).to, (Vec2{48, 0}));
}

TEST(EntityList, TwoCursorsReadApartAndAMovedListKeepsItsFile) {
  const auto entities = every_kind(50);
  EntityList moved = filled(entities, 500);
  const EntityList list = std::move(moved);
  auto a = list.begin();
  auto b = list.begin();
  for (int i = 0; i < 7; ++i)
    ++a;
  EXPECT_EQ(*b, entities[0]);
  EXPECT_EQ(*a, entities[7]);
  auto copy = a;
  ++a;
  EXPECT_EQ(*copy, entities[7]);
  EXPECT_EQ(*a, entities[8]);
}

TEST(EntityList, AFolderThatCannotHoldTheFileKeepsTheEntitiesInMemory) {
  const auto entities = every_kind(20);
  const EntityList list = filled(entities, 200, "/nonexistent/usina-folder");
  EXPECT_EQ(list.spilled(), 0u);
  EXPECT_EQ(list.to_vector(), entities);
}

TEST(EntityList, TheFileIsUnnamedAndGoesWithTheList) {
  Folder folder;
  {
    const EntityList list = filled(every_kind(20), 200, folder.path);
    ASSERT_GT(list.spilled(), 0u);
    EXPECT_TRUE(fs::is_empty(folder.path));
    EXPECT_GE(descriptor_in(folder.path), 0);
  }
  EXPECT_TRUE(descriptors_in(folder.path).empty());
}

TEST(EntityList, ADrawingsLayersShareOneFileAndOneLimit) {
  // Three hundred tools, their moves in turn (a layer each in the toolpath
  // view): one file, and the drawing holds its limit plus at most a
  // least spill a layer, not a layer's hold (64 KiB) three hundred times.
  Folder folder;
  constexpr std::size_t kLimit = 16 << 10;
  constexpr int kTools = 300;
  Drawing d;
  d.set_hold(EntityList::kHoldBytes, kLimit, folder.path);
  std::vector<std::vector<Entity>> drawn(kTools);
  for (int i = 0; i < 200; ++i) {
    for (int t = 0; t < kTools; ++t) {
      const Circle c{{1.0 * t, 1.0 * i}, 1.0};
      d.add_circle(d.layer(toolpath_layer(t + 1)), c);
      drawn[static_cast<std::size_t>(t)].emplace_back(c);
    }
  }
  EXPECT_EQ(descriptors_in(folder.path).size(), 1u);
  std::size_t held = 0;
  for (int t = 0; t < kTools; ++t) {
    const EntityList& list = d.layer(toolpath_layer(t + 1)).entities;
    held += (list.size() - list.spilled()) * sizeof(Entity);
    EXPECT_EQ(list.to_vector(), drawn[static_cast<std::size_t>(t)]) << t;
  }
  EXPECT_LE(held, kLimit + kTools * EntityList::kLeastSpill);
  EXPECT_LT(held, kTools * 200 * sizeof(Entity) / 2);
}

TEST(EntityList, AFileCutShortOrChangedFromOutsideIsAnErrorNotAGuess) {
  Folder folder;
  const EntityList list = filled(every_kind(20), 200, folder.path);
  const int fd = descriptor_in(folder.path);
  ASSERT_GE(fd, 0);
  EXPECT_EQ(list.to_vector().size(), list.size());
  EXPECT_EQ(list.read_error(), "");
  ASSERT_EQ(::pwrite(fd, "\x7f", 1, 0), 1);  // no entity's tag
  EXPECT_TRUE(list.to_vector().empty());
  EXPECT_EQ(list.read_error(),
            "the drawing's entities could not be read back from their temporary file in " +
                folder.path + ": Input/output error");
  ASSERT_EQ(::pwrite(fd, "\0", 1, 0), 1);  // a line's tag again
  EXPECT_EQ(list.to_vector().size(), list.size());
  EXPECT_EQ(list.read_error(), "");
  ASSERT_EQ(::ftruncate(fd, 40), 0);  // in the second entity's numbers
  EXPECT_LT(list.to_vector().size(), list.size());
  EXPECT_NE(list.read_error(), "");
}

// A spiral with its contour cut by two tools, and holes: the pictures of it
// are the same bytes whether its entities went to a file or not.
Drawing spiral_part(std::size_t hold, const std::string& folder = {}) {
  Drawing d;
  d.set_hold(hold, hold, folder);
  d.set_tolerance(0.01);
  Layer& contour = d.layer(kContourLayer);
  Vec2 at{0, 0};
  for (int i = 1; i <= 20'000; ++i) {
    if (i == 7'000) contour.tool_runs.push_back({contour.entities.size(), 2});
    if (i == 13'000) contour.tool_runs.push_back({contour.entities.size(), 5});
    const double theta = 0.01 * i;
    const Vec2 to{0.02 * i * std::cos(theta), 0.02 * i * std::sin(theta)};
    d.add_line(contour, at, to);
    if (i % 100 == 0) d.add_circle(d.layer(kHolesLayer), {to, 1.5});
    if (i % 1000 == 0) d.add_line(d.layer(kRapidLayer), to, {0, 0});
    at = to;
  }
  return d;
}

// What `write(FILE*)` wrote.
template <class Write>
std::string bytes_of(Write write) {
  std::FILE* f = std::tmpfile();
  EXPECT_TRUE(write(f).has_value());
  std::string out(static_cast<std::size_t>(std::ftell(f)), '\0');
  std::rewind(f);
  EXPECT_EQ(std::fread(out.data(), 1, out.size(), f), out.size());
  std::fclose(f);
  return out;
}

std::string dxf_of(const Drawing& d) {
  return bytes_of([&](std::FILE* f) { return write_dxf(d, f); });
}

std::string png_of(const Drawing& d) {
  return bytes_of([&](std::FILE* f) { return write_png(d, f, {800, 600}); });
}

std::string svg_of(const Drawing& d) {
  std::ostringstream out;
  EXPECT_TRUE(write_svg(d, out));
  return out.str();
}

TEST(EntityList, APictureIsTheSameWhetherItsEntitiesWentToAFileOrNot) {
  Drawing held = spiral_part(EntityList::kHoldBytes * 1000);
  Drawing spilled = spiral_part(2000);
  EXPECT_EQ(held.layer(kContourLayer).entities.spilled(), 0u);
  const Layer& contour = spilled.layer(kContourLayer);
  ASSERT_GT(contour.entities.spilled(), contour.entities.size() / 2);
  ASSERT_EQ(contour.tool_runs.size(), 2u);
  EXPECT_EQ(dxf_of(spilled), dxf_of(held));
  EXPECT_EQ(svg_of(spilled), svg_of(held));
  EXPECT_EQ(png_of(spilled), png_of(held));
}

TEST(EntityList, AWriterThatCannotReadItsDrawingBackLeavesTheFileAsItWas) {
  Folder folder;
  const Drawing d = spiral_part(2000, folder.path);
  const std::string out = folder.path + "/part";
  for (const char* ext : {".dxf", ".svg", ".png", ".pdf"}) {
    std::FILE* f = std::fopen((out + ext).c_str(), "w");
    std::fputs("the shop's drawing", f);
    std::fclose(f);
  }
  const int fd = descriptor_in(folder.path);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::ftruncate(fd, 1000), 0);
  const std::string why =
      "the drawing's entities could not be read back from their temporary "
      "file in " +
      folder.path + ": Input/output error";
  EXPECT_EQ(write_dxf_file(d, out + ".dxf").error(), why);
  EXPECT_EQ(write_svg_file(d, out + ".svg").error(), why);
  EXPECT_EQ(write_png_file(d, out + ".png", {400, 300}).error(), why);
  EXPECT_EQ(write_pdf_file(d, out + ".pdf").error(), why);
  for (const char* ext : {".dxf", ".svg", ".png", ".pdf"}) {
    std::ifstream in(out + ext);
    EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), "the shop's drawing") << ext;
  }
  EXPECT_EQ(d.read_error(), why);
}

}  // namespace
}  // namespace usina::draw
