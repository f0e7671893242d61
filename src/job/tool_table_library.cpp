#include "job/tool_table_library.hpp"

#include <charconv>
#include <cmath>
#include <map>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "gcode/tool_table.hpp"
#include "job/toml_reader.hpp"

namespace usina::job {
namespace {

// What a comment says of one tool, each at most once.
struct Said {
  std::optional<ToolType> type;
  std::optional<ToolMaterial> material;
  std::optional<double> flutes, cutting_length, overall_length, pitch, angle, tip_diameter;
};

constexpr ToolType kAllTypes[] = {
    ToolType::Flat,    ToolType::Ball, ToolType::Bull,     ToolType::Drill, ToolType::Spot,
    ToolType::Chamfer, ToolType::Tap,  ToolType::Engraver, ToolType::Face,  ToolType::Bore};
constexpr ToolMaterial kAllMaterials[] = {ToolMaterial::Hss, ToolMaterial::Carbide,
                                          ToolMaterial::Coated};

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out)
    c = (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
  return out;
}

std::optional<double> positive(std::string_view s) {
  double v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size() || !std::isfinite(v) || v <= 0 || v > 1e5)
    return std::nullopt;
  return v;
}

// "3-flute", "3-flutes", "3flute", "z3": the flutes; nullopt for any other word.
std::optional<double> flutes_word(const std::string& w) {
  if (w.size() > 1 && w[0] == 'z') return positive(std::string_view(w).substr(1));
  for (const char* tail : {"-flutes", "-flute", "flutes", "flute"}) {
    if (w.ends_with(tail))
      return positive(std::string_view(w).substr(0, w.size() - std::string_view(tail).size()));
  }
  return std::nullopt;
}

class CommentReader {
 public:
  CommentReader(const gcode::ToolEntry& e, core::SourceLoc loc, double mm_per_unit,
                core::DiagnosticSink& diags)
      : e_(e), loc_(loc), unit_(mm_per_unit), diags_(diags) {}

  // False after an error.
  bool read(Said& said) {
    std::string text = e_.comment;
    for (char& c : text)
      if (c == ',') c = ' ';
    std::size_t at = 0;
    while (ok_ && at < text.size()) {
      const std::size_t end = std::min(text.find(' ', at), text.size());
      if (end > at) word(lower(std::string_view(text).substr(at, end - at)), said);
      at = end + 1;
    }
    return ok_;
  }

  void fail(std::string message) {
    diags_.report({core::Code::BadToolLibrary, core::Severity::Error, loc_,
                   fmt::format("tool {}: {}", e_.number, message)});
    ok_ = false;
  }

 private:
  template <class T>
  void set(std::optional<T>& slot, T value, std::string_view what, std::string_view word) {
    if (slot && *slot != value) {
      fail(
          fmt::format("its comment gives its {} twice, differently (\"{}\" and \"{}\"): it "
                      "is not clear; say it once",
                      what, first_[std::string(what)], word));
      return;
    }
    if (!slot) first_[std::string(what)] = word;
    slot = value;
  }

  void length(std::optional<double>& slot, std::string_view key, std::string_view value,
              double scale) {
    const auto v = positive(value);
    if (!v) return fail(fmt::format("{}={} is not a positive number", key, value));
    set(slot, *v * scale, key, value);
  }

  void key_value(const std::string& key, const std::string& value, Said& said) {
    if (key == "type") {
      for (ToolType t : kAllTypes)
        if (value == tool_type_name(t)) return set(said.type, t, "type", value);
      return fail(fmt::format("type={} is not a tool type usina knows", value));
    }
    if (key == "material") {
      for (ToolMaterial m : kAllMaterials)
        if (value == tool_material_name(m)) return set(said.material, m, "tool material", value);
      return fail(fmt::format("material={}: give hss, carbide or coated", value));
    }
    if (key == "flutes") return length(said.flutes, key, value, 1.0);
    if (key == "cutting_length") return length(said.cutting_length, key, value, unit_);
    if (key == "overall_length") return length(said.overall_length, key, value, unit_);
    if (key == "pitch") return length(said.pitch, key, value, unit_);
    if (key == "angle") return length(said.angle, key, value, 1.0);
    if (key == "tip_diameter") return length(said.tip_diameter, key, value, unit_);
    fail(
        fmt::format("its comment's {}= is not a key usina reads there: type, material, flutes, "
                    "cutting_length, overall_length, pitch, angle, tip_diameter",
                    key));
  }

  void word(const std::string& w, Said& said) {
    if (const std::size_t eq = w.find('='); eq != std::string::npos)
      return key_value(w.substr(0, eq), w.substr(eq + 1), said);
    for (ToolType t : kAllTypes)
      if (w == tool_type_name(t)) return set(said.type, t, "type", w);
    for (ToolMaterial m : kAllMaterials)
      if (w == tool_material_name(m)) return set(said.material, m, "tool material", w);
    if (const auto f = flutes_word(w)) return set(said.flutes, *f, "flutes", w);
  }

  const gcode::ToolEntry& e_;
  core::SourceLoc loc_;
  double unit_;
  core::DiagnosticSink& diags_;
  bool ok_ = true;
  std::map<std::string, std::string> first_;  // the word that first gave each thing
};

bool mills(ToolType t) {
  return t == ToolType::Flat || t == ToolType::Ball || t == ToolType::Bull || t == ToolType::Face ||
         t == ToolType::Chamfer || t == ToolType::Engraver;
}

// What the job needs and the table does not say: from the comment, else an
// error that says how to give it.
std::optional<Tool> tool_of(const gcode::ToolEntry& e, core::SourceLoc loc, double mm_per_unit,
                            core::DiagnosticSink& diags) {
  CommentReader r(e, loc, mm_per_unit, diags);
  Said said;
  if (!r.read(said)) return std::nullopt;
  // What to write, and the tool's line with a word of it added.
  const auto missing = [&](std::string_view what, std::string_view how, std::string_view word) {
    r.fail(fmt::format(
        "the table does not give its {}: give it in its comment ({}), e.g. "
        "\"T{} P{} D{:g} ;{}{}{}\"",
        what, how, e.number, e.pocket, e.diameter, e.comment, e.comment.empty() ? "" : " ", word));
    return std::nullopt;
  };
  if (!(e.diameter > 0)) {
    r.fail(fmt::format("the table gives it no diameter: add its D word (T{} P{} D6.0 ...)",
                       e.number, e.pocket));
    return std::nullopt;
  }
  if (!said.type)
    return missing("type", "flat, ball, bull, drill, spot, chamfer, tap, engraver, face or bore",
                   "flat");
  if (!said.material) return missing("tool material", "hss, carbide or coated", "carbide");
  if (!said.cutting_length)
    return missing("cutting length", "cutting_length=", "cutting_length=22");
  if (!said.flutes && mills(*said.type))
    return missing("flutes (a cutter's feed is per tooth)", "3-flute, z3 or flutes=3", "3-flute");
  if (*said.type == ToolType::Chamfer && !said.angle)
    return missing("included angle (a chamfer mill's depth and path follow from it)",
                   "angle=", "angle=90");
  Tool t;
  t.number = e.number;
  t.type = *said.type;
  t.name = e.comment;
  t.diameter = e.diameter;
  t.flutes = static_cast<int>(said.flutes.value_or(2));
  t.cutting_length = *said.cutting_length;
  t.overall_length = said.overall_length.value_or(0);
  t.pitch = said.pitch.value_or(0);
  t.angle = said.angle.value_or(0);
  t.tip_diameter = said.tip_diameter.value_or(0);
  t.material = *said.material;
  const bool cone = t.type == ToolType::Chamfer || t.type == ToolType::Engraver;
  if ((t.pitch > 0 && t.type != ToolType::Tap) || ((t.angle > 0 || said.tip_diameter) && !cone)) {
    r.fail("only a tap has a pitch, only a chamfer mill or an engraver an angle or a tip_diameter");
    return std::nullopt;
  }
  return t;
}

}  // namespace

std::optional<std::vector<Tool>> read_tool_table_library(const core::SourceFile& file,
                                                         std::uint32_t file_id, double mm_per_unit,
                                                         core::DiagnosticSink& diags) {
  core::DiagnosticList table_diags;
  const auto table = gcode::read_tool_table(file, file_id, mm_per_unit, table_diags);
  bool ok = table.has_value();
  for (const core::Diagnostic& d : table_diags.all()) {
    ok = ok && d.severity != core::Severity::Error;
    diags.report(d);
  }
  if (!ok) return std::nullopt;
  const LineStarts lines(file.text());
  std::vector<Tool> tools;
  for (const gcode::ToolEntry& e : table->entries()) {
    const core::SourceLoc loc{file_id, e.line, 1, 0, lines.offset(e.line)};
    if (auto t = tool_of(e, loc, mm_per_unit, diags)) {
      tools.push_back(std::move(*t));
    } else {
      ok = false;
    }
  }
  if (!ok) return std::nullopt;
  return tools;
}

}  // namespace usina::job
