// The helpers of the usina command (usina-serve, usina-raster.so) are found
// beside the running executable and nowhere else: usina runs as root, so
// neither PATH, the working folder nor an environment variable may choose
// the code it runs.
#pragma once

#include <string>
#include <string_view>

#include <tl/expected.hpp>

namespace usina::cli {

// The path of `name` in the folder of the running executable
// (/proc/self/exe), or why that folder cannot be known.
tl::expected<std::string, std::string> beside_executable(std::string_view name);

}  // namespace usina::cli
