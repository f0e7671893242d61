#include "apt/iso4343.hpp"

#include <fmt/format.h>

#include "apt/vocabulary.hpp"

namespace usina::apt {
namespace {

// At most 9 decimals (a nanometre in mm), without trailing zeros: what a
// post reads, not 17 digits of a rounding residue.
std::string number(double v) {
  std::string t = fmt::format("{:.9f}", v);
  while (t.back() == '0')
    t.pop_back();
  if (t.back() == '.') t.pop_back();
  return t == "-0" ? "0" : t;
}

// Text as a statement may hold it: no line break or control character, no
// ',' or '/' that would split an argument.
std::string plain(std::string_view t, bool argument) {
  std::string out;
  for (const char c : t) {
    const bool control = static_cast<unsigned char>(c) < 0x20 || c == 0x7f;
    out.push_back(control || (argument && (c == ',' || c == '/' || c == '$')) ? ' ' : c);
  }
  while (!out.empty() && out.back() == ' ')
    out.pop_back();
  while (!out.empty() && out.front() == ' ')
    out.erase(out.begin());
  return out;
}

std::string word(const ClWord& w) {
  if (w.kind == ClWord::Kind::Real) return number(w.real);
  if (w.kind == ClWord::Kind::Text) return plain(w.text, true);
  const std::string_view name = minor_word_name(w.code);
  return name.empty() ? std::to_string(w.code) : std::string(name);
}

std::string args(const std::vector<ClWord>& words, std::size_t from = 0) {
  std::string out;
  for (std::size_t i = from; i < words.size(); ++i)
    out += (i > from ? "," : "") + word(words[i]);
  return out;
}

std::string text_of(const ClRecord& r) {
  std::string t;
  for (const ClWord& w : r.words)
    t += w.text;
  return plain(t, false);
}

class Writer {
 public:
  explicit Writer(const std::vector<ClRecord>& records) : records_(records) {}

  std::string run(std::string_view units);

 private:
  void record(std::size_t i);
  void post(const ClRecord& r);
  void motion(const ClRecord& r);
  void circle(std::size_t i);

  void line(const std::string& s) { out_ += s + "\n"; }

  const std::vector<ClRecord>& records_;
  std::string out_;
  bool rapid_ = false;       // RAPID: each point of the next motion statement
  bool rapid_used_ = false;  // ... and it has begun
};

std::string Writer::run(std::string_view units) {
  if (!units.empty()) line(fmt::format("UNITS/{}", units));
  for (std::size_t i = 0; i < records_.size(); ++i)
    record(i);
  return out_;
}

void Writer::record(std::size_t i) {
  const ClRecord& r = records_[i];
  switch (r.cls) {
  case cls::kSource:
    if (rapid_used_) rapid_ = rapid_used_ = false;
    return;
  case cls::kPost: return post(r);
  case cls::kSurface: return circle(i);
  case cls::kMotion: return motion(r);
  case cls::kControl: {
    const char* name = r.sub == 4 ? "INTOL" : r.sub == 5 ? "OUTTOL" : r.sub == 6 ? "CUTTER" : "";
    if (*name != '\0') return line(fmt::format("{}/{}", name, args(r.words)));
    break;
  }
  case cls::kFini: return line("FINI");
  default: break;
  }
  line(fmt::format("$$ record {} {}: {}", r.cls, r.sub, args(r.words)));
}

void Writer::post(const ClRecord& r) {
  if (r.sub == post_code("RAPID")) {
    rapid_ = true;
    return;
  }
  const std::string_view name = post_word_name(r.sub);
  if (name.empty()) return line(fmt::format("$$ record 2000 {}: {}", r.sub, args(r.words)));
  if (r.sub == post_code("PPRINT") || r.sub == post_code("PARTNO") || r.sub == post_code("INSERT"))
    return line(fmt::format("{}/{}", name, text_of(r)));
  if (r.words.empty()) return line(std::string(name));
  line(fmt::format("{}/{}", name, args(r.words)));
}

void Writer::motion(const ClRecord& r) {
  const char* name = r.sub == 3 ? "FROM" : "GOTO";
  for (std::size_t i = 2; i + 2 < r.words.size(); i += 3) {
    if (rapid_) {
      if (r.sub != 3) line("RAPID");  // FROM traverses without it
      rapid_used_ = true;
    }
    line(fmt::format("{}/{},{},{}", name, word(r.words[i]), word(r.words[i + 1]),
                     word(r.words[i + 2])));
  }
}

// 3000 2: 0, #4, #9, name, 0, then xc,yc,zc, i,j,k, r.
void Writer::circle(std::size_t i) {
  const ClRecord& r = records_[i];
  std::size_t next = i + 1;
  while (next < records_.size() && records_[next].cls != cls::kMotion)
    ++next;
  const bool arc = next < records_.size() && records_[next].words.size() == 5;
  if (r.sub == 2 && r.words.size() == 12 && arc)
    return line(fmt::format("CIRCLE/{}", args(r.words, 5)));
  line(fmt::format("$$ CIRCLE/{} (its chords follow)", args(r.words, 5)));
}

}  // namespace

std::string write_iso4343(const std::vector<ClRecord>& records, std::string_view units) {
  return Writer(records).run(units);
}

}  // namespace usina::apt
