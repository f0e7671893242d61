// Loads usina-raster.so (cli/raster_module.hpp) from the folder of the
// running executable only: usina runs as root, so no search path, working
// folder or environment variable may choose the code it loads.
#include <dlfcn.h>

#include <string>

#include <fmt/format.h>

#include "cli/beside_executable.hpp"
#include "cli/raster_module.hpp"

namespace usina::cli {
namespace {

tl::expected<const RasterWriters*, std::string> load() {
  const auto path = beside_executable(kRasterModuleName);
  if (!path) return tl::unexpected(path.error());
  const std::string what = fmt::format(
      "cannot load {}, the module that writes PNG and PDF (installed beside usina)", *path);
  // A path with a slash: dlopen loads that file and searches nowhere.
  void* module = ::dlopen(path->c_str(), RTLD_NOW | RTLD_LOCAL);
  if (module == nullptr) {
    const char* error = ::dlerror();
    std::string why = error != nullptr ? error : "unknown error";
    if (why.starts_with(*path + ": ")) why.erase(0, path->size() + 2);  // named already
    return tl::unexpected(fmt::format("{}: {}", what, why));
  }
  using Entry = const RasterWriters* (*)();
  void* symbol = ::dlsym(module, "usina_raster_writers");
  // POSIX: a function's address may be read from dlsym's void*.
  const auto entry = reinterpret_cast<Entry>(symbol);
  const RasterWriters* writers = entry != nullptr ? entry() : nullptr;
  if (writers == nullptr || writers->abi != kRasterModuleAbi ||
      std::string(writers->version) != USINA_VERSION) {
    ::dlclose(module);
    return tl::unexpected(
        fmt::format("{}: it is not the module of this usina {} (install both from one build)", what,
                    USINA_VERSION));
  }
  return writers;  // loaded for the rest of the run
}

}  // namespace

tl::expected<const RasterWriters*, std::string> raster_writers() {
  static const tl::expected<const RasterWriters*, std::string> writers = load();
  return writers;
}

}  // namespace usina::cli
