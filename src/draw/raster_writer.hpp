// PNG and PDF pictures of a drawing through cairo: the drawing fitted to the
// image or page (y up), each layer in its colour (tool layers by tool,
// rapids dashed), a legend of the layers that have entities, a scale bar.
#pragma once

#include <string>

#include "draw/drawing.hpp"
#include "draw/write_result.hpp"

namespace usina::draw {

struct PixelSize {
  int width = 1600;
  int height = 1200;
};

// The most pixels a PNG may have (25 million: 100 MB of image in memory).
inline constexpr long kMaxPngPixels = 25'000'000;

WriteResult write_png(const Drawing& drawing, std::FILE* file, PixelSize size);

// An A4 page, landscape when the drawing is wider than tall.
WriteResult write_pdf(const Drawing& drawing, std::FILE* file);

// Through core::OutputFile; `inputs` may not be the output.
WriteResult write_png_file(const Drawing& drawing, const std::string& path, PixelSize size,
                           const std::vector<std::string>& inputs = {});
WriteResult write_pdf_file(const Drawing& drawing, const std::string& path,
                           const std::vector<std::string>& inputs = {});

}  // namespace usina::draw
