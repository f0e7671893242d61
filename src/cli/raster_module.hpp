// The PNG and PDF writers (cairo's) as a module of their own,
// usina-raster.so beside the usina executable, loaded only by the verbs
// that write such a picture: cairo and its libraries (pixman, fontconfig,
// freetype, X11) stay off every other verb's start-up (docs/performance.md,
// "Start-up").
#pragma once

#include <cstdio>
#include <string>

#include <tl/expected.hpp>

#include "cli/simulate_images.hpp"
#include "core/document.hpp"
#include "draw/drawing.hpp"
#include "draw/raster_writer.hpp"
#include "draw/write_result.hpp"

namespace usina::cli {

// The file name of the module, beside the usina executable.
inline constexpr const char* kRasterModuleName = "usina-raster.so";

// Changed whenever RasterWriters changes: a module of another build is
// refused, not called.
inline constexpr int kRasterModuleAbi = 2;

// What the module gives: the writers, called on the caller's data (usina
// and the module are one build, one compiler, one C++ library).
struct RasterWriters {
  int abi;
  const char* version;  // USINA_VERSION of the module's build
  draw::WriteResult (*write_png)(const draw::Drawing& drawing, std::FILE* file,
                                 draw::PixelSize size);
  draw::WriteResult (*write_pdf)(const draw::Drawing& drawing, std::FILE* file);
  tl::expected<void, std::string> (*write_stock_png)(const sim::stock::HeightMap& map,
                                                     StockView view, std::FILE* file);
  // A document (usina job's setup sheet) as A4 pages; `figure` at its Figure block.
  draw::WriteResult (*write_sheet_pdf)(const core::Document& doc, const draw::Drawing& figure,
                                       std::FILE* file);
};

// The module's writers, loaded on the first call; or why they cannot be
// (the message names the file).
tl::expected<const RasterWriters*, std::string> raster_writers();

}  // namespace usina::cli

// The one symbol the module exports.
extern "C" const usina::cli::RasterWriters* usina_raster_writers();
