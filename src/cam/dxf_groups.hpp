// The group pairs of an ASCII DXF file, read and checked before dxflib sees
// them. dxflib trusts its input: its line reader never ends on a line of
// 1,024 bytes or more (the stream's fail state is never cleared, end of file
// never reached), it sizes arrays by the counts a file declares (LWPOLYLINE
// group 90, SPLINE 72/73/74, LEADER 76) and it writes before its vertex array
// on a bulge (42) that comes before the first vertex. So usina splits the lines
// itself, checks every group and the counts against what follows, and hands
// dxflib a canonical copy: "code\nvalue\n" pairs, each line within dxflib's
// limit, comments (999) left out, ending at the EOF group.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "core/diagnostic.hpp"

namespace usina::cam {

// The longest line dxflib reads (DL_DXF_MAXLINE - 1, without the line end).
// AutoCAD writes at most 255 characters in a value, 2,049 since R2007.
inline constexpr std::size_t kMaxDxfLineLength = 1023;

// The text of `bytes` for dxflib, or nullopt after an error that names `name`
// and the line: E_DXF_UNREADABLE when the bytes are not a text file (a NUL
// byte, a binary DXF), E_DXF_MALFORMED when the lines are not a DXF's groups
// (a code that is not an integer, a line too long, a count that does not
// match its items, no EOF group).
std::optional<std::string> canonical_dxf(std::string_view bytes, const std::string& name,
                                         core::DiagnosticSink& diags);

}  // namespace usina::cam
