// A document as HTML (job/sheet_html.cpp): each kind of block in its
// element, every text escaped, a cell's line breaks kept, the small
// columns marked, the picture put at the figure's place as it was given.
#include <string>

#include <gtest/gtest.h>

#include "job/sheet.hpp"

namespace usina::job {
namespace {

using Kind = core::DocBlock::Kind;

TEST(SheetHtml, EachBlockIsItsElementAndEveryTextIsEscaped) {
  core::Document doc;
  doc.title = "Setup sheet: <A&B>";
  doc.heading("Tools & holders");
  core::DocBlock facts(Kind::Facts);
  facts.rows = {{"Setup", "vise\nparallels \"10\""}};
  doc.blocks.push_back(facts);
  core::DocBlock table(Kind::Table);
  table.header = {"T", "Why"};
  table.small = {false, true};
  table.rows = {{"T1", "first\nsecond"}};
  doc.blocks.push_back(table);
  core::DocBlock list(Kind::List);
  list.rows = {{"warning: feed > 5000"}};
  doc.blocks.push_back(list);
  doc.figure("from above");
  doc.note("it's a note");
  const std::string h = document_html(doc, "<svg id=\"p\"></svg>");
  EXPECT_EQ(h.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(h.find("<title>Setup sheet: &lt;A&amp;B&gt;</title>"), std::string::npos) << h;
  EXPECT_NE(h.find("<h1>Setup sheet: &lt;A&amp;B&gt;</h1>"), std::string::npos);
  EXPECT_NE(h.find("<h2>Tools &amp; holders</h2>"), std::string::npos);
  EXPECT_NE(h.find("<tr><th scope=\"row\">Setup</th><td>vise<br>parallels &quot;10&quot;</td>"),
            std::string::npos);
  EXPECT_NE(h.find("<th scope=\"col\">T</th><th scope=\"col\">Why</th>"), std::string::npos);
  EXPECT_NE(h.find("<tr><td>T1</td><td class=\"why\">first<br>second</td></tr>"),
            std::string::npos);
  EXPECT_NE(h.find("<li>warning: feed &gt; 5000</li>"), std::string::npos);
  EXPECT_NE(h.find("<figure>\n<svg id=\"p\"></svg>\n<figcaption>from above</figcaption>"),
            std::string::npos);
  EXPECT_NE(h.find("<p class=\"note\">it&#39;s a note</p>"), std::string::npos);
  EXPECT_EQ(h.find("<A&B>"), std::string::npos);
}

TEST(SheetHtml, ARowShorterThanTheHeaderAndAnEmptyListItemStillMakeAPage) {
  core::Document doc;
  doc.title = "t";
  core::DocBlock facts(Kind::Facts);
  facts.rows = {{"only a name"}};  // no value: left out, not read past its end
  doc.blocks.push_back(facts);
  core::DocBlock list(Kind::List);
  list.rows = {{}};
  doc.blocks.push_back(list);
  const std::string h = document_html(doc, "");
  EXPECT_EQ(h.find("only a name"), std::string::npos);
  EXPECT_NE(h.find("<li></li>"), std::string::npos);
  EXPECT_NE(h.find("</body>\n</html>\n"), std::string::npos);
}

}  // namespace
}  // namespace usina::job
