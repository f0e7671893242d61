#include "apt/cldata.hpp"

#include <bit>
#include <cmath>
#include <cstring>

#include <fmt/format.h>

#include "apt/cl_text.hpp"

namespace usina::apt {
namespace {

constexpr std::size_t kHeaderBytes = 16;
constexpr std::size_t kWordBytes = 8;
// A real this small is a rounding residue; written as 0, since its bytes
// (those of 2^-509 and below) could read as a text word's two blanks.
constexpr double kSmallest = 1e-150;

void put_u32(std::string& out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i)
    out.push_back(static_cast<char>((v >> (8 * i)) & 0xffu));
}

void put_u64(std::string& out, std::uint64_t v) {
  for (int i = 0; i < 8; ++i)
    out.push_back(static_cast<char>((v >> (8 * i)) & 0xffu));
}

std::uint32_t get_u32(std::string_view b, std::size_t at) {
  std::uint32_t v = 0;
  for (int i = 3; i >= 0; --i)
    v = (v << 8) | static_cast<unsigned char>(b[at + static_cast<std::size_t>(i)]);
  return v;
}

std::uint64_t get_u64(std::string_view b, std::size_t at) {
  std::uint64_t v = 0;
  for (int i = 7; i >= 0; --i)
    v = (v << 8) | static_cast<unsigned char>(b[at + static_cast<std::size_t>(i)]);
  return v;
}

void put_word(std::string& out, const ClWord& w) {
  if (w.kind == ClWord::Kind::Code) {
    put_u64(out, static_cast<std::uint32_t>(w.code));
  } else if (w.kind == ClWord::Kind::Text) {
    std::string t = w.text.substr(0, 6);
    t.resize(8, ' ');
    out += t;
  } else {
    const double v = std::fabs(w.real) < kSmallest ? 0.0 : w.real;
    put_u64(out, std::bit_cast<std::uint64_t>(v));
  }
}

// A word's kind is in its bytes: a code has 0 in its high 32 bits (a real
// there would be subnormal), text ends in two blanks (a real there would be
// below 1e-150, which the writer never writes).
ClWord get_word(std::string_view b, std::size_t at) {
  const std::uint64_t bits = get_u64(b, at);
  if (bits != 0 && (bits >> 32) == 0)
    return ClWord::vocabulary(static_cast<int>(static_cast<std::uint32_t>(bits)));
  if (b[at + 6] == ' ' && b[at + 7] == ' ') return ClWord::chars(std::string(b.substr(at, 6)));
  const double v = std::bit_cast<double>(bits);
  return ClWord::number(std::fabs(v) < kSmallest ? 0.0 : v);  // as the writer writes it
}

class Reader {
 public:
  Reader(std::string_view bytes, std::uint32_t file, core::DiagnosticSink& diags)
      : b_(bytes), file_(file), diags_(diags) {}

  // The next record into `r`; false at the end or at a broken record.
  bool next(ClRecord& r);

  std::size_t count() const { return recno_; }

 private:
  bool fail(std::size_t at, const std::string& why) {
    diags_.report(core::Diagnostic{core::Code::ClBadRecord, core::Severity::Error, loc(at),
                                   fmt::format("record {} (byte {}): {}", recno_ + 1, at, why)});
    return false;
  }

  core::SourceLoc loc(std::size_t at) const {
    return core::SourceLoc{file_, static_cast<std::uint32_t>(recno_ + 1), 1, 0, at};
  }

  std::string_view b_;
  std::uint32_t file_;
  core::DiagnosticSink& diags_;
  std::size_t at_ = 0;
  std::size_t recno_ = 0;
};

bool Reader::next(ClRecord& r) {
  if (at_ == b_.size()) return false;
  const std::size_t at = at_;
  if (b_.size() - at < kHeaderBytes)
    return fail(at, fmt::format("the file ends inside the record's header ({} of {} bytes)",
                                b_.size() - at, kHeaderBytes));
  const std::uint32_t recno = get_u32(b_, at);
  const std::uint32_t nwords = get_u32(b_, at + 4);
  if (recno != recno_ + 1)
    return fail(at, fmt::format("numbered {}, expected {}: this is not CLDATA, or it is damaged",
                                recno, recno_ + 1));
  if (nwords > kMostCldataWords)
    return fail(at, fmt::format("{} words; a record holds at most {}", nwords, kMostCldataWords));
  if ((b_.size() - at - kHeaderBytes) / kWordBytes < nwords)
    return fail(at, fmt::format("the file ends inside the record's {} words", nwords));
  r.cls = static_cast<int>(get_u32(b_, at + 8));
  r.sub = static_cast<int>(get_u32(b_, at + 12));
  r.words.clear();
  for (std::uint32_t i = 0; i < nwords; ++i) {
    r.words.push_back(get_word(b_, at + kHeaderBytes + kWordBytes * i));
    const ClWord& w = r.words.back();
    if (w.kind == ClWord::Kind::Real && !std::isfinite(w.real))
      return fail(at, fmt::format("word {} is not a finite number", i + 1));
    // As in a CL text file: no coordinate or feed is this large, and a
    // larger one scaled to mm could overflow.
    if (w.kind == ClWord::Kind::Real && std::fabs(w.real) > kLargestClNumber)
      return fail(at, fmt::format("word {} is {:g}, beyond {:g}", i + 1, w.real, kLargestClNumber));
  }
  r.src = loc(at);
  at_ = at + kHeaderBytes + kWordBytes * nwords;
  ++recno_;
  return true;
}

}  // namespace

std::string write_cldata(const std::vector<ClRecord>& records, std::uint32_t first) {
  std::string out;
  std::uint32_t recno = first - 1;
  for (const ClRecord& r : records) {
    put_u32(out, ++recno);
    put_u32(out, static_cast<std::uint32_t>(r.words.size()));
    put_u32(out, static_cast<std::uint32_t>(r.cls));
    put_u32(out, static_cast<std::uint32_t>(r.sub));
    for (const ClWord& w : r.words)
      put_word(out, w);
  }
  return out;
}

std::size_t read_cldata(std::string_view bytes, std::uint32_t file, core::DiagnosticSink& diags,
                        const std::function<bool(ClRecord&&)>& take) {
  Reader reader(bytes, file, diags);
  ClRecord r;
  while (reader.next(r))
    if (!take(std::move(r))) break;
  return reader.count();
}

std::vector<ClRecord> read_cldata(std::string_view bytes, std::uint32_t file,
                                  core::DiagnosticSink& diags) {
  std::vector<ClRecord> out;
  read_cldata(bytes, file, diags, [&out](ClRecord&& r) {
    out.push_back(std::move(r));
    return true;
  });
  return out;
}

}  // namespace usina::apt
