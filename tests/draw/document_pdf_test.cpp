// A document as PDF (draw/document_pdf): A4 pages whose text is the
// document's; a table longer than a page carries on with its header on
// every page; a cell longer than a page is split between pages and loses
// no line; a word wider than its column is broken, not lost; a failed
// write is an error.
#include "draw/document_pdf.hpp"

#include <cstdio>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "support/files.hpp"
#include "support/pdf.hpp"

namespace usina::draw {
namespace {

using Kind = core::DocBlock::Kind;

// The PDF of `doc` (with a square as its figure) in `dir`; its path.
std::string written(const core::Document& doc, const test::TempDir& dir) {
  Drawing figure;
  figure.layer("CONTOUR").entities.push_back(Polyline{{{0, 0}, {50, 0}, {50, 50}, {0, 50}}, true});
  const std::string path = dir.path("doc.pdf");
  std::FILE* f = std::fopen(path.c_str(), "wb");
  EXPECT_NE(f, nullptr);
  if (f == nullptr) return path;
  const WriteResult w = write_document_pdf(doc, figure, f);
  EXPECT_TRUE(w) << (w ? "" : w.error());
  std::fclose(f);
  return path;
}

core::DocBlock table_of(std::size_t rows) {
  core::DocBlock t{Kind::Table};
  t.header = {"Number", "Square", "Remark"};
  t.small = {false, false, true};
  for (std::size_t i = 1; i <= rows; ++i)
    t.rows.push_back({fmt::format("row{}", i), fmt::format("{}", i * i), "a remark"});
  return t;
}

TEST(DocumentPdf, AShortDocumentIsOneA4PageWithItsText) {
  const test::TempDir dir;
  core::Document doc;
  doc.title = "Setup sheet: bracket";
  doc.heading("Tools");
  core::DocBlock facts{Kind::Facts};
  facts.rows = {{"Stock", "box 100 × 80 × 20 mm"}, {"Setup", "vise, parallels 10 mm"}};
  doc.blocks.push_back(facts);
  doc.figure("seen from above");
  doc.blocks.push_back(table_of(3));
  core::DocBlock list{Kind::List};
  list.rows = {{"warning: a feed past the machine's"}, {}};  // an empty item too
  doc.blocks.push_back(list);
  doc.note("a note at the end");
  const std::string bytes = test::slurp(written(doc, dir));
  EXPECT_EQ(bytes.rfind("%PDF-", 0), 0u);
  EXPECT_EQ(test::pdf_pages(bytes), 1u);
  EXPECT_NE(bytes.find("/MediaBox [ 0 0 595.28 841.89 ]"), std::string::npos);  // A4 portrait
  const auto text = test::pdf_text(dir.path("doc.pdf"));
  if (!text) GTEST_SKIP() << "pdftotext (poppler-utils) is not installed";
  for (const char* part :
       {"Setup sheet: bracket", "Tools", "box 100 × 80 × 20 mm", "row3", "9", "seen from above",
        "warning: a feed past the machine's", "a note at the end", "page 1"})
    EXPECT_NE(text->find(part), std::string::npos) << part << "\n" << *text;
}

TEST(DocumentPdf, ALongTableCarriesOnWithItsHeaderOnEveryPage) {
  const test::TempDir dir;
  core::Document doc;
  doc.title = "Squares";
  doc.blocks.push_back(table_of(200));  // 200 rows of 16 pt: more than four pages of 758 pt
  const std::string path = written(doc, dir);
  const std::size_t pages = test::pdf_pages(test::slurp(path));
  EXPECT_GE(pages, 5u);
  EXPECT_LE(pages, 6u);
  const auto text = test::pdf_text(path);
  if (!text) GTEST_SKIP() << "pdftotext (poppler-utils) is not installed";
  EXPECT_EQ(test::count(*text, "Number"), pages) << *text;
  EXPECT_NE(text->find("row200"), std::string::npos);
  EXPECT_NE(text->find(fmt::format("Squares — page {}", pages)), std::string::npos);
  for (std::size_t i = 1; i <= 200; ++i)
    EXPECT_NE(text->find(fmt::format("row{} ", i)), std::string::npos)
        << i;  // -layout: a line a row
}

TEST(DocumentPdf, ACellLongerThanAPageIsSplitAndLosesNoLine) {
  const test::TempDir dir;
  core::Document doc;
  doc.title = "Long";
  core::DocBlock t{Kind::Table};
  t.header = {"Op", "Why"};
  std::string why;
  for (int i = 1; i <= 150; ++i)
    why += fmt::format("{}reason{}", i == 1 ? "" : "\n", i);
  t.rows = {{"1", why}, {"2", "short"}};
  doc.blocks.push_back(t);
  const std::string path = written(doc, dir);
  // 150 lines of 11 pt, 1,658 pt: started on the first page under the
  // title, carried on over two more.
  EXPECT_EQ(test::pdf_pages(test::slurp(path)), 3u);
  const auto text = test::pdf_text(path);
  if (!text) GTEST_SKIP() << "pdftotext (poppler-utils) is not installed";
  for (int i = 1; i <= 150; ++i)
    EXPECT_NE(text->find(fmt::format("reason{}\n", i)), std::string::npos) << i;
  EXPECT_NE(text->find("short"), std::string::npos);
}

TEST(DocumentPdf, AHeaderTallerThanHalfAPageIsAFirstRowNotRepeated) {
  const test::TempDir dir;
  core::Document doc;
  doc.title = "Odd";
  core::DocBlock t{Kind::Table};
  std::string tall;
  for (int i = 0; i < 100; ++i)
    tall += "h\n";
  t.header = {tall, "x"};
  t.rows = {{"first", "1"}, {"second", "2"}};
  doc.blocks.push_back(t);
  const std::string path = written(doc, dir);
  // The header (1,100 pt) over two pages, not repeated; the rows after it.
  EXPECT_EQ(test::pdf_pages(test::slurp(path)), 2u);
  const auto text = test::pdf_text(path);
  if (!text) GTEST_SKIP() << "pdftotext (poppler-utils) is not installed";
  EXPECT_NE(text->find("first"), std::string::npos);
  EXPECT_NE(text->find("second"), std::string::npos);
  EXPECT_EQ(test::count(*text, "h\n"), 99u);  // and the first, beside the x
}

TEST(DocumentPdf, AWordWiderThanItsColumnIsBrokenNotLost) {
  const test::TempDir dir;
  core::Document doc;
  doc.title = "Words";
  const std::string word(400, 'x');
  doc.note(word);
  const std::string path = written(doc, dir);
  const auto text = test::pdf_text(path);
  if (!text) GTEST_SKIP() << "pdftotext (poppler-utils) is not installed";
  EXPECT_EQ(test::count(*text, "x"), 400u);
  EXPECT_EQ(text->find(word), std::string::npos);  // not on one line: it would leave the page
}

TEST(DocumentPdf, AFailedWriteIsAnError) {
  std::FILE* full = std::fopen("/dev/full", "wb");
  if (full == nullptr) GTEST_SKIP() << "no /dev/full";
  std::setvbuf(full, nullptr, _IONBF, 0);
  core::Document doc;
  doc.title = "Nowhere";
  doc.blocks.push_back(table_of(50));
  const WriteResult w = write_document_pdf(doc, Drawing{}, full);
  std::fclose(full);
  EXPECT_FALSE(w);
}

}  // namespace
}  // namespace usina::draw
