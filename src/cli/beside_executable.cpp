#include "cli/beside_executable.hpp"

#include <filesystem>
#include <system_error>

namespace usina::cli {

tl::expected<std::string, std::string> beside_executable(std::string_view name) {
  std::error_code ec;
  // The kernel's own record of the file being run: not argv[0], which the
  // caller chooses.
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec)
    return tl::unexpected("cannot find the usina executable (/proc/self/exe): " + ec.message());
  return (self.parent_path() / name).string();
}

}  // namespace usina::cli
