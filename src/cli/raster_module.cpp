// usina-raster.so: cairo's PNG and PDF writers, for usina draw, usina
// simulate and usina job's PDF sheet (cli/raster_module.hpp says why they
// are a module).
#include "cli/raster_module.hpp"

#include "draw/document_pdf.hpp"

namespace {

constexpr usina::cli::RasterWriters kWriters{
    usina::cli::kRasterModuleAbi, USINA_VERSION,
    usina::draw::write_png,       usina::draw::write_pdf,
    usina::cli::write_stock_png,  usina::draw::write_document_pdf,
};

}  // namespace

extern "C" __attribute__((visibility("default"))) const usina::cli::RasterWriters*
usina_raster_writers() {
  return &kWriters;
}
