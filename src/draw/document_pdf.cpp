#include "draw/document_pdf.hpp"

#include <cairo.h>

#include <algorithm>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <cairo-pdf.h>
#include <fmt/format.h>

#include "draw/finite.hpp"
#include "draw/raster_render.hpp"

namespace usina::draw {
namespace {

// A4 portrait in PostScript points, and the layout's measures (points).
constexpr double kPageWidth = 595.28;
constexpr double kPageHeight = 841.89;
constexpr double kMargin = 42.0;  // about 15 mm
constexpr double kWidth = kPageWidth - 2.0 * kMargin;
constexpr double kBottom = kPageHeight - kMargin;
constexpr double kPad = 2.5;  // inside a table's cell
constexpr double kIndent = 10.0;
constexpr double kMinFigure = 160.0;  // the figure's least height

struct Font {
  double size;
  bool bold;
};

constexpr Font kTitle{16.0, true};
constexpr Font kHeading{12.0, true};
constexpr Font kBody{8.5, false};
constexpr Font kBold{8.5, true};
constexpr Font kSmall{7.0, false};

double line_height(Font f) {
  return 1.3 * f.size;
}

// The index after the UTF-8 character at `i`: a word too long for its
// column is broken between characters, never inside one.
std::size_t next_char(std::string_view s, std::size_t i) {
  ++i;
  while (i < s.size() && (static_cast<unsigned char>(s[i]) & 0xC0) == 0x80)
    ++i;
  return i;
}

// The pages written so far and where the next line goes (y down).
class Pages {
 public:
  Pages(cairo_t* cr, std::string footer) : cr_(cr), footer_(std::move(footer)) {}

  cairo_t* cr() const { return cr_; }

  double room() const { return kBottom - y; }

  bool at_top() const { return y <= kMargin; }

  // Starts a new page unless `height` fits on this one (or this one is empty).
  void need(double height) {
    if (height > room() && !at_top()) next();
  }

  void next() {
    end_page();
    y = kMargin;
  }

  void end_page() {
    use_font(kSmall);
    cairo_set_source_rgb(cr_, 0.4, 0.4, 0.4);
    const std::string text = fmt::format("{} — page {}", footer_, page_++);
    cairo_move_to(cr_, kPageWidth - kMargin - width(text), kPageHeight - kMargin / 2.0);
    cairo_show_text(cr_, text.c_str());
    cairo_show_page(cr_);
  }

  void use_font(Font f) {
    cairo_select_font_face(cr_, "sans-serif", CAIRO_FONT_SLANT_NORMAL,
                           f.bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr_, f.size);
  }

  // In the font in use.
  double width(const std::string& text) {
    cairo_text_extents_t ext;
    cairo_text_extents(cr_, text.c_str(), &ext);
    return ext.x_advance;
  }

  void text(double x, double baseline, const std::string& s) {
    cairo_set_source_rgb(cr_, 0.07, 0.07, 0.07);
    cairo_move_to(cr_, x, baseline);
    cairo_show_text(cr_, s.c_str());
  }

  double y = kMargin;

 private:
  cairo_t* cr_;
  std::string footer_;
  int page_ = 1;
};

// `word` in lines of at most `width` (at least one character a line).
void break_word(Pages& p, std::string word, double width, std::vector<std::string>& lines,
                std::string& line) {
  while (p.width(word) > width) {
    std::size_t cut = next_char(word, 0);
    for (std::size_t at = cut; at < word.size(); at = next_char(word, at)) {
      if (p.width(word.substr(0, next_char(word, at))) > width) break;
      cut = next_char(word, at);
    }
    lines.push_back(word.substr(0, cut));
    word.erase(0, cut);
  }
  line = std::move(word);
}

// The text's lines in `f` within `width`: its own line breaks kept, words
// moved down as they stop fitting.
std::vector<std::string> wrap(Pages& p, std::string_view text, Font f, double width) {
  p.use_font(f);
  std::vector<std::string> lines;
  std::size_t start = 0;
  for (;;) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    std::string line;
    std::string_view rest = text.substr(start, end - start);
    while (!rest.empty()) {
      const std::size_t space = std::min(rest.find(' '), rest.size());
      std::string word(rest.substr(0, space));
      rest.remove_prefix(std::min(space + 1, rest.size()));
      if (word.empty()) continue;
      std::string candidate = line;
      if (!candidate.empty()) candidate += ' ';
      candidate += word;
      if (p.width(candidate) <= width) {
        line = std::move(candidate);
        continue;
      }
      if (!line.empty()) lines.push_back(std::move(line));
      break_word(p, std::move(word), width, lines, line);
    }
    lines.push_back(std::move(line));
    if (end >= text.size()) return lines;
    start = end + 1;
  }
}

void paragraph(Pages& p, std::string_view text, Font f, double x, double width) {
  const double lh = line_height(f);
  for (const std::string& line : wrap(p, text, f, width)) {
    p.need(lh);
    p.use_font(f);
    p.text(x, p.y + f.size, line);
    p.y += lh;
  }
}

struct Cell {
  std::vector<std::string> lines;
  Font font;
};

// Rows of cells in columns of given widths; a row that does not fit on the
// page goes to the next one, after the header again; a row taller than a
// page is split between its lines, from where it stands.
class TableWriter {
 public:
  TableWriter(Pages& p, std::vector<double> widths, std::vector<Cell> header)
      : p_(p), widths_(std::move(widths)), header_(std::move(header)) {}

  void start() {
    // A header taller than half a page is not repeated: it is the table's
    // first row, split between pages as a row is.
    if (height(header_, {}) > (kBottom - kMargin) / 2.0) {
      const std::vector<Cell> once = std::move(header_);
      header_.clear();
      top_ = p_.at_top();
      row(once);
      return;
    }
    p_.need(height(header_, {}) + 3.0 * line_height(kBody) + 2.0 * kPad);
    const bool fresh = p_.at_top();
    draw_header();
    top_ = fresh;
  }

  void row(const std::vector<Cell>& cells) {
    std::vector<std::size_t> next(cells.size(), 0);
    for (;;) {
      const double h = height(cells, next);
      if (h <= p_.room()) {
        draw(cells, next, h - 2.0 * kPad, false);
        break;
      }
      // A row that fits on a page of its own goes there whole; a taller
      // one starts here.
      if (!top_ && h <= kBottom - kMargin - height(header_, {})) {
        p_.next();
        draw_header();
        continue;
      }
      draw(cells, next, p_.room() - 2.0 * kPad, false);
      if (height(cells, next) <= 2.0 * kPad) break;  // every line is out (a page without room)
      p_.next();
      draw_header();
    }
    top_ = false;
  }

 private:
  static double height(const std::vector<Cell>& cells, const std::vector<std::size_t>& next) {
    double h = 0.0;
    for (std::size_t i = 0; i < cells.size(); ++i) {
      const std::size_t done = i < next.size() ? next[i] : 0;
      const auto left =
          static_cast<double>(cells[i].lines.size() - std::min(done, cells[i].lines.size()));
      h = std::max(h, left * line_height(cells[i].font));
    }
    return h + 2.0 * kPad;
  }

  void draw_header() {
    if (!header_.empty()) {
      std::vector<std::size_t> next(header_.size(), 0);
      draw(header_, next, height(header_, next) - 2.0 * kPad, true);
    }
    top_ = true;
  }

  // The lines of each cell from `next` that fit in `budget` (one at the
  // least, so a row always moves on), its borders; `next` moved past them.
  void draw(const std::vector<Cell>& cells, std::vector<std::size_t>& next, double budget,
            bool shaded) {
    std::vector<std::size_t> count(cells.size(), 0);
    double used = 0.0;
    for (std::size_t i = 0; i < cells.size() && i < widths_.size(); ++i) {
      const double lh = line_height(cells[i].font);
      const std::size_t left = cells[i].lines.size() - std::min(next[i], cells[i].lines.size());
      const auto fit = static_cast<std::size_t>(std::max(0.0, budget / lh));  // no room: 0
      count[i] = std::min(left, std::max<std::size_t>(1, fit));
      used = std::max(used, static_cast<double>(count[i]) * lh);
    }
    const double h = used + 2.0 * kPad;
    cairo_t* cr = p_.cr();
    double x = kMargin;
    for (std::size_t i = 0; i < cells.size() && i < widths_.size(); ++i) {
      if (shaded) {
        cairo_set_source_rgb(cr, 0.9, 0.9, 0.9);
        cairo_rectangle(cr, x, p_.y, widths_[i], h);
        cairo_fill(cr);
      }
      p_.use_font(cells[i].font);
      const double lh = line_height(cells[i].font);
      for (std::size_t k = 0; k < count[i]; ++k) {
        p_.text(x + kPad, p_.y + kPad + static_cast<double>(k) * lh + cells[i].font.size,
                cells[i].lines[next[i] + k]);
      }
      next[i] += count[i];
      cairo_set_source_rgb(cr, 0.6, 0.6, 0.6);
      cairo_set_line_width(cr, 0.5);
      cairo_rectangle(cr, x, p_.y, widths_[i], h);
      cairo_stroke(cr);
      x += widths_[i];
    }
    p_.y += h;
  }

  Pages& p_;
  std::vector<double> widths_;
  std::vector<Cell> header_;
  bool top_ = false;  // nothing but the header on this page yet
};

// The widest line and the widest word of `text` in `f`.
std::pair<double, double> measure(Pages& p, std::string_view text, Font f) {
  p.use_font(f);
  double line = 0.0;
  double word = 0.0;
  for (const std::string& l : wrap(p, text, f, 1e9)) {
    line = std::max(line, p.width(l));
    std::size_t start = 0;
    while (start <= l.size()) {
      const std::size_t end = std::min(l.find(' ', start), l.size());
      word = std::max(word, p.width(l.substr(start, end - start)));
      start = end + 1;
    }
  }
  return {line, word};
}

// Each column its widest line when they all fit; else each its widest word
// (at most 40 % of the page) and the rest of the width shared in
// proportion to what each would like more.
std::vector<double> column_widths(Pages& p, const std::vector<std::vector<std::string>>& rows,
                                  const std::vector<std::vector<Font>>& fonts) {
  const std::size_t n = rows.empty() ? 0 : rows.front().size();
  std::vector<double> natural(n, 0.0);
  std::vector<double> least(n, 0.0);
  for (std::size_t r = 0; r < rows.size(); ++r) {
    for (std::size_t i = 0; i < n && i < rows[r].size(); ++i) {
      const auto [line, word] = measure(p, rows[r][i], fonts[r][i]);
      natural[i] = std::max(natural[i], line + 2.0 * kPad + 1.0);
      least[i] = std::max(least[i], std::min(word + 2.0 * kPad + 1.0, 0.4 * kWidth));
    }
  }
  double sum_natural = 0.0;
  double sum_least = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    sum_natural += natural[i];
    sum_least += least[i];
  }
  if (sum_natural <= kWidth) return natural;
  std::vector<double> widths(n);
  for (std::size_t i = 0; i < n; ++i) {
    widths[i] = sum_least >= kWidth ? least[i] * kWidth / sum_least
                                    : least[i] + (kWidth - sum_least) * (natural[i] - least[i]) /
                                                     std::max(sum_natural - sum_least, 1e-9);
  }
  return widths;
}

std::vector<Cell> cells_of(Pages& p, const std::vector<std::string>& texts,
                           const std::vector<Font>& fonts, const std::vector<double>& widths) {
  std::vector<Cell> cells;
  for (std::size_t i = 0; i < texts.size() && i < widths.size(); ++i)
    cells.push_back({wrap(p, texts[i], fonts[i], widths[i] - 2.0 * kPad), fonts[i]});
  return cells;
}

// A Table (its header bold and shaded) or Facts (the names bold, no header).
void table(Pages& p, const core::DocBlock& b) {
  const bool facts = b.kind == core::DocBlock::Kind::Facts;
  std::vector<std::vector<std::string>> rows;
  std::vector<std::vector<Font>> fonts;
  if (!facts) {
    rows.push_back(b.header);
    fonts.emplace_back(b.header.size(), kBold);
  }
  for (const auto& r : b.rows) {
    rows.push_back(r);
    rows.back().resize(rows.front().size());
    std::vector<Font> f(r.size(), kBody);
    for (std::size_t i = 0; i < f.size(); ++i)
      f[i] = facts && i == 0 ? kBold : i < b.small.size() && b.small[i] ? kSmall : kBody;
    f.resize(rows.front().size(), kBody);
    fonts.push_back(std::move(f));
  }
  if (rows.empty() || rows.front().empty()) return;
  const std::vector<double> widths =
      facts ? std::vector<double>{0.22 * kWidth, 0.78 * kWidth} : column_widths(p, rows, fonts);
  TableWriter writer(p, widths,
                     facts ? std::vector<Cell>{} : cells_of(p, rows[0], fonts[0], widths));
  writer.start();
  for (std::size_t r = facts ? 0 : 1; r < rows.size(); ++r)
    writer.row(cells_of(p, rows[r], fonts[r], widths));
  p.y += 8.0;
}

void figure(Pages& p, const core::DocBlock& b, const Drawing& drawing) {
  const Box box = finite_view_box(drawing);
  // Its width the page's; its height the drawing's, and the legend's strip.
  double h =
      std::clamp(kWidth * box.height() / std::max(box.width(), 1e-9) + 30.0, kMinFigure, 380.0);
  // Smaller, down to kMinFigure, rather than leave the rest of a page empty.
  const double caption = 2.0 * line_height(kSmall) + 4.0;  // its gap, two lines, a hair
  if (h + caption > p.room() && p.room() - caption >= kMinFigure) h = p.room() - caption;
  p.need(h + caption);
  render_drawing(p.cr(), drawing, {kMargin, p.y, kWidth, h}, 0.6);
  cairo_set_source_rgb(p.cr(), 0.6, 0.6, 0.6);
  cairo_set_line_width(p.cr(), 0.5);
  cairo_rectangle(p.cr(), kMargin, p.y, kWidth, h);
  cairo_stroke(p.cr());
  p.y += h + 3.0;
  paragraph(p, b.text, kSmall, kMargin, kWidth);
  p.y += 8.0;
}

void block(Pages& p, const core::DocBlock& b, const Drawing& drawing) {
  using Kind = core::DocBlock::Kind;
  switch (b.kind) {
  case Kind::Heading:
    // Kept with a few lines of what follows it.
    p.need(line_height(kHeading) + 4.0 * line_height(kBody));
    paragraph(p, b.text, kHeading, kMargin, kWidth);
    p.y += 3.0;
    break;
  case Kind::Facts:
  case Kind::Table: table(p, b); break;
  case Kind::Note:
    paragraph(p, b.text, kSmall, kMargin, kWidth);
    p.y += 6.0;
    break;
  case Kind::List:
    for (const auto& item : b.rows) {
      p.need(line_height(kBody));
      p.use_font(kBody);
      p.text(kMargin, p.y + kBody.size, "•");
      paragraph(p, item.empty() ? "" : item[0], kBody, kMargin + kIndent, kWidth - kIndent);
    }
    p.y += 6.0;
    break;
  case Kind::Figure: figure(p, b, drawing); break;
  }
}

}  // namespace

WriteResult write_document_pdf(const core::Document& doc, const Drawing& figure, std::FILE* file) {
  Surface surface(
      cairo_pdf_surface_create_for_stream(write_to_stream, file, kPageWidth, kPageHeight));
  if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS)
    return tl::unexpected(status_text(cairo_surface_status(surface.get())));
  cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_TITLE, doc.title.c_str());
  cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_CREATOR, "usina");
  {
    Context cr(cairo_create(surface.get()));
    Pages pages(cr.get(), doc.title);
    paragraph(pages, doc.title, kTitle, kMargin, kWidth);
    pages.y += 6.0;
    for (const core::DocBlock& b : doc.blocks)
      block(pages, b, figure);
    pages.end_page();
    if (cairo_status(cr.get()) != CAIRO_STATUS_SUCCESS)
      return tl::unexpected(status_text(cairo_status(cr.get())));
  }
  if (auto error = figure.read_error()) return tl::unexpected(*error);
  return finish_surface(surface.get());
}

}  // namespace usina::draw
