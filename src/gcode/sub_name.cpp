#include "gcode/sub_name.hpp"

#include <fmt/format.h>

namespace usina::gcode {

tl::expected<void, std::string> subroutine_name_problem(std::string_view name) {
  // NAME_MAX of Linux, less the ".ngc" added to the name.
  constexpr std::size_t kMaxName = 255 - 4;
  if (name.empty()) return tl::unexpected<std::string>("the name is empty");
  for (const char c : name) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '/' || c == '\\') {
      return tl::unexpected(fmt::format(
          "it contains '{}': a subroutine name is a file name, not a path; put <name>.ngc in a "
          "folder of --subroutine-path instead",
          c));
    }
    if (byte < 0x20 || byte == 0x7f) {
      return tl::unexpected(fmt::format(
          "it contains the control byte 0x{:02x}, which no file name should hold", byte));
    }
  }
  if (name.front() == '.') {
    return tl::unexpected<std::string>(
        "it starts with '.': a subroutine file is never '..' or a hidden file");
  }
  if (name.size() > kMaxName) {
    return tl::unexpected(fmt::format(
        "it is {} bytes long; a file name holds at most {} besides '.ngc'", name.size(), kMaxName));
  }
  return {};
}

}  // namespace usina::gcode
