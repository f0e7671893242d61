#include "apt/cl_text.hpp"

#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "apt/cl_text_reader.hpp"
#include "apt/vocabulary.hpp"

namespace usina::apt::detail {
namespace {

// Words that place, paint or name and move nothing: read, no record.
bool is_silent(const std::string& w) {
  return w == "PAINT" || w == "MSYS" || w == "CSYS" || w == "TRNTYP" || w == "END-OF-PATH" ||
         w == "MULTAX" || w == "TPRINT" || w == "KNOT" || w == "CNTRL" || w.starts_with("CSI_");
}

// PARTNO/'text' as modern CAM writes it: the text without its quotes.
std::string unquoted(const std::string& t) {
  if (t.size() >= 2 && t.front() == '\'' && t.back() == '\'') return t.substr(1, t.size() - 2);
  return t;
}

constexpr double kMostToolNumber = 999999;

// LOADTL/n, LOAD/TOOL,n: n a whole number a control can hold.
bool tool_number(const ClStatement& st) {
  for (const ClArg& a : st.args)
    if (a.kind == ClArg::Kind::Number)
      return a.value >= 0 && a.value <= kMostToolNumber && a.value == std::floor(a.value);
  return false;
}

ClWord word_of(const ClArg& a) {
  if (a.kind == ClArg::Kind::Number) return ClWord::number(a.value);
  if (a.kind == ClArg::Kind::Word)
    if (const auto code = minor_word_code(a.text)) return ClWord::vocabulary(*code);
  return ClWord::chars(a.text.substr(0, 6));
}

}  // namespace

bool ClTextReader::statement(const ClStatement& st) {
  recs_.clear();
  const bool ok = dispatch(st);
  if (ok && !recs_.empty()) flush(st);
  return !stop_;
}

void ClTextReader::flush(const ClStatement& st) {
  ClRecord isn{cls::kSource,
               static_cast<int>(st.loc.line),
               {ClWord::number(0.0), ClWord::chars("")},
               st.loc};
  if (out_.record && !out_.record(std::move(isn))) stop_ = true;
  for (ClRecord& r : recs_)
    if (!stop_ && out_.record && !out_.record(std::move(r))) stop_ = true;
}

bool ClTextReader::dispatch(const ClStatement& st) {
  const std::string& w = st.major;
  if (circle_ && (w == "FROM" || w == "GODLTA" || w == "CIRCLE" || w == "FINI"))
    circle_left_out("another motion comes before the GOTO/ of its end");
  if (w == "GOTO") return point(st, 5);
  if (w == "FROM") return point(st, 3);
  if (w == "GODLTA") return godlta(st);
  if (w == "CIRCLE") return circle(st);
  if (w == "RAPID") return add(cls::kPost, 5, {}, st.loc);
  if (w == "CYCLE") return cycle(st);
  if (w == "PARTNO" || w == "PPRINT" || w == "INSERT")
    return text(st, *post_word_code(w), unquoted(st.rest));
  if (w == "TOOL PATH") return text(st, post_code("PPRINT"), "TOOL PATH/" + st.rest);
  if (w == "REMARK" || w.empty() || is_silent(w)) return false;
  if (w == "FINI") {
    stop_ = true;
    return add(cls::kFini, 0, {}, st.loc);
  }
  if (w == "UNITS" || w == "UNIT") return units(st);
  if (w == "CUTTER" || w == "TLDATA") return control(st, 6);
  if (w == "INTOL") return control(st, 4);
  if (w == "OUTTOL") return control(st, 5);
  if (w == "LOAD") return post_word(st, 1055);  // NX: LOAD/TOOL,n[,ADJUST,h]
  if (w == "NURBS")
    return fail(core::Code::ClNotSupported, st.loc,
                "NURBS/ (a spline) is not read: usina reads lines and circles; the spline's "
                "end is reached by the next GOTO in a straight line");
  if (const auto code = post_word_code(w)) return post_word(st, *code);
  return fail(core::Code::ClIgnored, st.loc,
              fmt::format("{} is not a CL statement usina reads; left out", w),
              core::Severity::Warning);
}

bool ClTextReader::post_word(const ClStatement& st, int code) {
  if (code == post_code("LOADTL") && !tool_number(st))
    return fail(core::Code::ClBadArgument, st.loc,
                fmt::format("{}/ takes a tool number, a whole number from 0 to {}", st.major,
                            kMostToolNumber));
  std::vector<ClWord> words;
  for (const ClArg& a : st.args) {
    if (code == post_code("LOADTL") && a.kind == ClArg::Kind::Word && a.text == "TOOL") continue;
    words.push_back(word_of(a));
  }
  if (code == post_code("FEDRAT")) {  // FEDRAT/f[,MMPM] or /MMPM,f: kept for a cycle without a feed
    // A feed rate ends a drilling cycle: SolidWorks CAM writes no CYCLE/OFF
    // before a milling operation that follows one (its cycle carries its own
    // feed and lasts across a tool change).
    if (cycle_on_) add(cls::kPost, 1054, {ClWord::vocabulary(kOff)}, st.loc);
    cycle_on_ = false;
    for (const ClArg& a : st.args) {
      if (a.kind == ClArg::Kind::Number) feed_ = a.value;
      if (a.kind == ClArg::Kind::Word && (a.text == "IPM" || a.text == "MMPM"))
        feed_unit_ = a.text == "IPM" ? kIpm : kMmpm;
    }
  }
  return add(cls::kPost, code, std::move(words), st.loc);
}

bool ClTextReader::text(const ClStatement& st, int code, std::string t) {
  return add(cls::kPost, code, text_words(t, std::max<std::size_t>(11, (t.size() + 5) / 6)),
             st.loc);
}

// CUTTER/d,..., TLDATA/MILL,d,r,...: the numbers; INTOL, OUTTOL: the tolerances.
bool ClTextReader::control(const ClStatement& st, int sub) {
  std::vector<ClWord> words;
  for (const ClArg& a : st.args)
    if (a.kind == ClArg::Kind::Number) words.push_back(ClWord::number(a.value));
  if (words.empty())
    return fail(core::Code::ClBadArgument, st.loc, fmt::format("{} has no number", st.major));
  return add(cls::kControl, sub, std::move(words), st.loc);
}

bool ClTextReader::units(const ClStatement& st) {
  const std::string u = st.args.size() == 1 ? st.args[0].text : "";
  double scale = 0.0;
  if (u == "MM") scale = 1.0;
  if (u == "INCH" || u == "INCHES") scale = 25.4;
  if (scale == 0.0)
    return fail(core::Code::ClBadArgument, st.loc,
                fmt::format("{}/ takes MM or INCHES, not '{}'", st.major, st.rest));
  // Records go on statement by statement: those after this one are in its unit.
  if (out_.units) out_.units(scale);
  return false;
}

}  // namespace usina::apt::detail

namespace usina::apt {

void read_cl_text(std::string_view text, std::uint32_t file, ClDialect dialect,
                  core::DiagnosticSink& diags, const ClConsumer& out) {
  detail::ClTextReader reader(dialect, diags, out);
  for_each_cl_statement(text, file, diags,
                        [&reader](const ClStatement& st) { return reader.statement(st); });
  reader.end();
}

std::vector<ClRecord> read_cl_text(std::string_view text, std::uint32_t file, ClDialect dialect,
                                   core::DiagnosticSink& diags) {
  std::vector<ClRecord> records;
  ClConsumer out;
  out.record = [&records](ClRecord&& r) {
    records.push_back(std::move(r));
    return true;
  };
  read_cl_text(text, file, dialect, diags, out);
  return records;
}

}  // namespace usina::apt
