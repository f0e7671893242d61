// A printable document as plain data: a title and blocks (headings, tables
// of facts, tables, notes, lists, one figure). The setup sheet (job/sheet)
// says what it holds once, and each writer lays it out in its own format:
// HTML (job/sheet_html) and PDF through cairo (draw/document_pdf), so the
// two cannot say different things. It lives in core because the module
// that fills it (job) and the one that prints it (draw) may not use each
// other (DESIGN.md, "Modules").
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace usina::core {

struct DocBlock {
  enum class Kind {
    Heading,  // `text`
    Facts,    // `rows` of two cells: a name and its value
    Table,    // `header` and `rows`, one cell a column
    Note,     // `text`, a paragraph in small print
    List,     // `rows` of one cell, each an item
    Figure,   // the document's picture (the writer's), `text` its caption
  };

  explicit DocBlock(Kind k = Kind::Note, std::string t = {}) : kind(k), text(std::move(t)) {}

  Kind kind;
  std::string text;
  std::vector<std::string> header;
  // A cell's text may hold '\n': a line break the writers keep.
  std::vector<std::vector<std::string>> rows;
  // Table only: the columns of small print (long explanations).
  std::vector<bool> small;
};

struct Document {
  std::string title;
  std::vector<DocBlock> blocks;

  void heading(std::string text) { blocks.emplace_back(DocBlock::Kind::Heading, std::move(text)); }

  void note(std::string text) { blocks.emplace_back(DocBlock::Kind::Note, std::move(text)); }

  void figure(std::string caption) {
    blocks.emplace_back(DocBlock::Kind::Figure, std::move(caption));
  }
};

}  // namespace usina::core
