// A core::Document as a PDF through cairo (the setup sheet's PDF): A4
// portrait pages, the title and the blocks in order, tables whose columns
// share the page's width and whose rows carry on to the next page (the
// header repeated) when they do not fit, the figure drawn as `usina draw`
// draws a PDF, and each page's footer with the title and its number.
#pragma once

#include <cstdio>

#include "core/document.hpp"
#include "draw/drawing.hpp"
#include "draw/write_result.hpp"

namespace usina::draw {

// `figure`: the drawing at the document's Figure block.
WriteResult write_document_pdf(const core::Document& doc, const Drawing& figure, std::FILE* file);

}  // namespace usina::draw
