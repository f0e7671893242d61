// The tool path of a revision for the web page's 3D viewer, as a compact
// binary stream (docs/web.md, "The tool-path stream"). The program runs
// through the interpreter in its dialect. Every move becomes vertices:
// arcs and splines linearised, each vertex tagged with the kind of the move
// that ends there, its tool and its source line. Then the path is
// decimated to at most `max_vertices`, so a program of a million blocks
// still reaches the browser in a few megabytes. Each vertex also carries
// when the tool reaches it: the program's time on the machine profile, as
// `stats` plans it, for the viewer's replay.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "sim/stats.hpp"

namespace usina::dnc {

// The kind of the move that ends at a vertex (one byte in the stream).
enum class PathKind : std::uint8_t {
  Start = 0,
  Rapid = 1,
  Feed = 2,
  Arc = 3,
  Spline = 4,
  Probe = 5
};

struct PathVertex {
  float x = 0.0f;
  float y = 0.0f;
  float z = 0.0f;
  PathKind kind = PathKind::Start;
  std::uint32_t tool = 0;  // the tool in the spindle (0 before the first change)
  std::uint32_t line = 0;  // the source line of the block that made the move
  float t = 0.0f;          // seconds from the program's start when the tool gets here
};

struct ToolpathSettings {
  std::string dialect = "rs274ngc";
  std::uint32_t max_vertices = 200'000;      // after decimation
  std::uint64_t max_ops = 100'000'000;       // canon operations, as the check
  std::uint64_t max_collected = 20'000'000;  // vertices before decimation
  // Times the vertices (the machine class's profile; the revision's check
  // and tool figures use the same, so the replay ends at their cycle time).
  sim::MachineProfile profile = sim::default_machine_profile();
};

struct ToolpathResult {
  std::vector<PathVertex> vertices;
  std::uint64_t moves = 0;      // motion ops the program made
  std::uint64_t collected = 0;  // vertices before decimation
  double total_s = 0.0;         // the program's time on the profile (waits after the last move too)
  bool truncated = false;       // max_collected was reached: the rest is not shown
  bool ok = true;               // false: the dialect is unknown or the run stopped on an error
};

ToolpathResult program_toolpath(std::string_view text, const ToolpathSettings& settings);

// Keeps at most `max_vertices` of `path`: vertices closer than a tolerance
// to the last kept one (of the same kind and tool) merge into it; the
// tolerance doubles until the path fits, and a path that still does not
// fit (kinds or tools alternating at every move) is sampled evenly. The
// first and last vertices are always kept.
std::vector<PathVertex> decimate(const std::vector<PathVertex>& path, std::uint32_t max_vertices);

// The stream's bytes (little-endian): the 56-byte header (its last field
// the program's time, float64 s), then the positions (3 × float32 a
// vertex), the lines (uint32), the tools (uint32), the times (float32 s),
// the kinds (uint8).
std::string encode_toolpath(const ToolpathResult& r);

inline constexpr std::uint32_t kToolpathMagic = 0x50545355;  // "USTP" little-endian
inline constexpr std::uint32_t kToolpathVersion = 2;
inline constexpr std::size_t kToolpathHeaderBytes = 56;
inline constexpr std::size_t kToolpathVertexBytes = 25;

}  // namespace usina::dnc
