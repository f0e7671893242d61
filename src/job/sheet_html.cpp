// A core::Document as one printable HTML page (the setup sheet's HTML).
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "job/sheet.hpp"

namespace usina::job {
namespace {

// Text from the job's author, the tool library and the drawing: escaped
// wherever it goes into the page; a line break of a cell becomes <br>.
std::string esc(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (const char c : s) {
    switch (c) {
    case '&': out += "&amp;"; break;
    case '<': out += "&lt;"; break;
    case '>': out += "&gt;"; break;
    case '"': out += "&quot;"; break;
    case '\'': out += "&#39;"; break;
    case '\n': out += "<br>"; break;
    default: out += c;
    }
  }
  return out;
}

constexpr std::string_view kStyle = R"(body{font-family:sans-serif;margin:1.5em;color:#111}
table{border-collapse:collapse;margin:.5em 0 1em}th,td{border:1px solid #999;padding:.25em .5em;
text-align:left;vertical-align:top}td.why{font-size:.85em}p.note{font-size:.85em}
figure svg{max-width:100%;height:auto;max-height:14cm;border:1px solid #999}
@media print{body{margin:0}h2{break-after:avoid}tr{break-inside:avoid}})";

void facts_html(std::string& h, const core::DocBlock& b) {
  h += "<table class=\"facts\">\n";
  for (const auto& row : b.rows) {
    if (row.size() < 2) continue;
    h += fmt::format("<tr><th scope=\"row\">{}</th><td>{}</td></tr>\n", esc(row[0]), esc(row[1]));
  }
  h += "</table>\n";
}

void table_html(std::string& h, const core::DocBlock& b) {
  h += "<table>\n<thead><tr>";
  for (const std::string& c : b.header)
    h += fmt::format("<th scope=\"col\">{}</th>", esc(c));
  h += "</tr></thead>\n<tbody>\n";
  for (const auto& row : b.rows) {
    h += "<tr>";
    for (std::size_t i = 0; i < row.size(); ++i) {
      const bool small = i < b.small.size() && b.small[i];
      h += fmt::format("<td{}>{}</td>", small ? " class=\"why\"" : "", esc(row[i]));
    }
    h += "</tr>\n";
  }
  h += "</tbody>\n</table>\n";
}

void block_html(std::string& h, const core::DocBlock& b, std::string_view picture_svg) {
  using Kind = core::DocBlock::Kind;
  switch (b.kind) {
  case Kind::Heading: h += fmt::format("<h2>{}</h2>\n", esc(b.text)); break;
  case Kind::Facts: facts_html(h, b); break;
  case Kind::Table: table_html(h, b); break;
  case Kind::Note: h += fmt::format("<p class=\"note\">{}</p>\n", esc(b.text)); break;
  case Kind::List:
    h += "<ul>\n";
    for (const auto& row : b.rows)
      h += fmt::format("<li>{}</li>\n", row.empty() ? "" : esc(row[0]));
    h += "</ul>\n";
    break;
  case Kind::Figure:
    // The picture is the caller's SVG, written by usina: not escaped.
    h += fmt::format("<figure>\n{}\n<figcaption>{}</figcaption>\n</figure>\n", picture_svg,
                     esc(b.text));
    break;
  }
}

}  // namespace

std::string document_html(const core::Document& doc, std::string_view picture_svg) {
  std::string h = fmt::format(
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>{}</title>\n"
      "<style>{}</style>\n</head>\n<body>\n<h1>{}</h1>\n",
      esc(doc.title), kStyle, esc(doc.title));
  for (const core::DocBlock& b : doc.blocks)
    block_html(h, b, picture_svg);
  h += "</body>\n</html>\n";
  return h;
}

}  // namespace usina::job
