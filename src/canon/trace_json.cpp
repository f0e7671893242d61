#include "canon/trace_json.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include <fmt/compile.h>

#include "core/text.hpp"

namespace usina::canon {
namespace {

// Appends to the line's buffer through a cursor of its own: fmt's appender
// asks for room at every character (a fifth of `usina trace` on a large
// program), and asking the buffer for room and its size at every piece
// was a twentieth of its instructions still. The buffer learns its size
// when the line is done (or before fmt writes to it).
class Out {
 public:
  explicit Out(fmt::memory_buffer& buf) : buf_(buf) { sync(); }

  Out(const Out&) = delete;
  Out& operator=(const Out&) = delete;

  ~Out() { commit(); }

  Out& operator<<(std::string_view s) {
    char* p = room(s.size());
    std::memcpy(p, s.data(), s.size());
    end_at(p + s.size());
    return *this;
  }

  Out& operator<<(char c) {
    char* p = room(1);
    *p = c;
    end_at(p + 1);
    return *this;
  }

  void integer(long long v);
  void num(double v);

 private:
  // Where n more characters go (written, then end_at() after them).
  char* room(std::size_t n) {
    if (static_cast<std::size_t>(end_ - cur_) < n) grow(n);
    return cur_;
  }

  void end_at(char* p) { cur_ = p; }

  // Room for n more characters and then some: a line of a few hundred
  // characters grows the buffer once at most.
  [[gnu::noinline]] void grow(std::size_t n) {
    constexpr std::size_t kSome = 512;
    commit();
    buf_.try_reserve(buf_.size() + std::max(n, kSome));
    sync();
    // fmt's memory buffer grows as asked or throws; any other would
    // leave the cursor short of room.
    if (static_cast<std::size_t>(end_ - cur_) < n) throw std::length_error("trace line buffer");
  }

  // The buffer's size where the cursor is, and back.
  void commit() { buf_.try_resize(static_cast<std::size_t>(cur_ - buf_.data())); }

  void sync() {
    cur_ = buf_.data() + buf_.size();
    end_ = buf_.data() + buf_.capacity();
  }

  void short_decimal(long long n);

  fmt::memory_buffer& buf_;
  char* cur_ = nullptr;
  char* end_ = nullptr;
};

// "00" to "99": two digits a division.
constexpr std::array<char, 200> kDigitPairs = [] {
  std::array<char, 200> t{};
  for (std::size_t i = 0; i < 100; ++i) {
    t[2 * i] = static_cast<char>('0' + i / 10);
    t[2 * i + 1] = static_cast<char>('0' + i % 10);
  }
  return t;
}();

// Writes the two digits of v < 100 at p.
void pair_at(char* p, unsigned long long v) {
  std::memcpy(p, &kDigitPairs[2 * v], 2);
}

// How many decimal digits u has.
std::size_t decimal_length(unsigned long long u) {
  std::size_t len = 1;
  for (; u >= 100; u /= 100)
    len += 2;
  return len + (u >= 10 ? 1 : 0);
}

// The decimal digits of u written at p, two at a time from the last: their
// end. In place: a copy of a few bytes of a length not known when
// compiling is a call to memmove.
char* digits_at(char* p, unsigned long long u) {
  char* const end = p + decimal_length(u);
  char* q = end;
  for (; u >= 100; u /= 100) {
    q -= 2;
    pair_at(q, u % 100);
  }
  if (u >= 10) {
    pair_at(q - 2, u);
  } else {
    q[-1] = static_cast<char>('0' + u);
  }
  return end;
}

unsigned long long magnitude(long long v) {
  return v < 0 ? 0ULL - static_cast<unsigned long long>(v) : static_cast<unsigned long long>(v);
}

// Room for a sign and the 20 digits of any long long.
constexpr std::size_t kIntegerRoom = 21;

void Out::integer(long long v) {
  char* p = room(kIntegerRoom);
  if (v < 0) *p++ = '-';
  end_at(digits_at(p, magnitude(v)));
}

// Writes `v` so that reading it back gives the same double; -0 as 0.
// Most coordinates are short decimals (12.345): when v is exactly the
// double nearest to n / 10^6 for an integer n, "n / 10^6" in decimal reads
// back as v, and writing it takes a few integer divisions instead of the
// shortest-representation search (the hot path of `usina trace`).
void Out::num(double v) {
  if (v == 0.0) v = 0.0;
  constexpr double kScale = 1e6;
  if (std::fabs(v) < 1e9) {
    // v * 10^6 to the nearest integer, halves away from zero (no libm
    // call); at most one n passes the test below, since 10^-6 is more than
    // an ulp of any v under 10^9.
    const double scaled = v * kScale;
    const auto n = static_cast<long long>(scaled + (scaled < 0 ? -0.5 : 0.5));
    if (static_cast<double>(n) / kScale == v) {
      short_decimal(n);
      return;
    }
  }
  commit();
  fmt::format_to(fmt::appender(buf_), FMT_COMPILE("{}"), v);
  sync();
}

// n / 10^6 in decimal, without trailing zeros: "-12.5", "3".
void Out::short_decimal(long long n) {
  constexpr unsigned long long kMillion = 1000000ULL;
  const unsigned long long u = magnitude(n);
  char* p = room(kIntegerRoom + 1 + 6);
  if (n < 0) *p++ = '-';
  p = digits_at(p, u / kMillion);
  const unsigned long long frac = u % kMillion;
  if (frac != 0) {
    // Six digits after the point, then back over the trailing zeros.
    *p = '.';
    pair_at(p + 1, frac / 10000);
    pair_at(p + 3, frac / 100 % 100);
    pair_at(p + 5, frac % 100);
    p += 6;
    while (*p == '0')
      --p;
    ++p;
  }
  end_at(p);
}

// A bored hole's cycle as the trace names it (a drilled hole says none).
const char* hole_cycle_name(HoleCycle c) {
  switch (c) {
  case HoleCycle::Bore: return "bore";
  case HoleCycle::BoreDwell: return "bore_dwell";
  case HoleCycle::BoreStop: return "bore_stop";
  case HoleCycle::Drill: break;
  }
  return "drill";
}

void vec(Out& out, const Vec3& v) {
  out << '[';
  out.num(v.x);
  out << ',';
  out.num(v.y);
  out << ',';
  out.num(v.z);
  out << ']';
}

void vec2(Out& out, const Vec2& v) {
  out << '[';
  out.num(v.x);
  out << ',';
  out.num(v.y);
  out << ']';
}

void abc(Out& out, const Abc& a) {
  if (a[0] == 0.0 && a[1] == 0.0 && a[2] == 0.0) return;
  out << ",\"abc\":";
  vec(out, {a[0], a[1], a[2]});
}

// A number, or null when there is none.
void num_or_null(Out& out, const std::optional<double>& v) {
  if (v) {
    out.num(*v);
  } else {
    out << "null";
  }
}

void feed(Out& out, const std::optional<double>& f) {
  out << ",\"f\":";
  num_or_null(out, f);
}

// An optional number, written only when there is one: ,"key":v
void optional_num(Out& out, std::string_view key, const std::optional<double>& v) {
  if (!v) return;
  out << key;
  out.num(*v);
}

// A JSON string of program text. Valid UTF-8 is copied; a byte that is not
// is read as Latin-1 (ISO 8859-1, the encoding of older controls' files:
// "(caf\xe9)" becomes "café"), so the line is always valid JSON
// (spec/trace.md).
void json_string(Out& out, std::string_view s) {
  out << '"';
  for (std::size_t i = 0; i < s.size();) {
    const char c = s[i];
    const auto u = static_cast<unsigned char>(c);
    const std::size_t n = core::utf8_sequence_at(s, i);
    if (c == '"' || c == '\\') {
      out << '\\' << c;
    } else if (u < 0x20 || u == 0x7F || n == 0) {
      constexpr std::string_view kHex = "0123456789abcdef";
      out << "\\u00" << kHex[u >> 4] << kHex[u & 0xF];
    } else {
      out << s.substr(i, n);
      i += n;
      continue;
    }
    ++i;
  }
  out << '"';
}

struct JsonFields {
  Out& out;

  void to(const Vec3& v) const {
    out << ",\"to\":";
    vec(out, v);
  }

  void operator()(const Traverse& m) const {
    to(m.to);
    abc(out, m.abc);
  }

  void operator()(const Feed& m) const {
    to(m.to);
    feed(out, m.f);
    abc(out, m.abc);
  }

  void operator()(const Arc& m) const {
    to(m.to);
    out << ",\"center\":";
    vec(out, m.center);
    out << ",\"normal\":";
    vec(out, m.normal);
    out << ",\"turn\":";
    out.integer(m.turn);
    feed(out, m.f);
    abc(out, m.abc);
  }

  void operator()(const Probe& m) const {
    to(m.to);
    abc(out, m.abc);
  }

  void operator()(const Spline& m) const {
    to(m.to);
    out << ",\"points\":[";
    for (std::size_t i = 0; i < m.points.size(); ++i) {
      if (i > 0) out << ',';
      vec(out, m.points[i]);
    }
    out << ']';
    feed(out, m.f);
  }

  void operator()(const Dwell& m) const {
    out << ",\"s\":";
    out.num(m.s);
  }

  void operator()(const ToolChange& m) const {
    out << ",\"tool\":";
    out.integer(m.tool);
    out << ",\"diameter\":";
    num_or_null(out, m.diameter);
  }

  void operator()(const Spindle& m) const {
    out << ",\"rpm\":";
    out.num(m.rpm);
    out << ",\"dir\":\"" << spindle_dir_name(m.dir) << '"';
  }

  void operator()(const Coolant& m) const {
    out << ",\"mist\":" << (m.mist ? "true" : "false")
        << ",\"flood\":" << (m.flood ? "true" : "false");
  }

  void operator()(const Hole& m) const {
    out << ",\"at\":";
    vec(out, m.at);
    out << ",\"diameter\":";
    out.num(m.diameter);
    out << ",\"depth\":";
    out.num(m.depth);
    // Only a bore says so: every drilled hole's trace stays as it was.
    if (m.cycle != HoleCycle::Drill) out << ",\"cycle\":\"" << hole_cycle_name(m.cycle) << '"';
    optional_num(out, ",\"f\":", m.f);
    if (m.cycle == HoleCycle::BoreDwell) {
      out << ",\"dwell\":";
      out.num(m.dwell);
    }
  }

  void operator()(const Pocket& m) const {
    out << ",\"outline\":{\"start\":";
    vec2(out, m.outline.start);
    out << ",\"segs\":[";
    bool first = true;
    for (const OutlineSegment& s : m.outline.segs) {
      out << (first ? "{\"to\":" : ",{\"to\":");
      first = false;
      vec2(out, s.to);
      if (s.center) {
        out << ",\"center\":";
        vec2(out, *s.center);
        out << ",\"turn\":";
        out.integer(s.turn);
      }
      out << '}';
    }
    out << "]},\"depth\":";
    out.num(m.depth);
  }

  void operator()(const Comment& m) const {
    out << ",\"text\":";
    json_string(out, m.text);
  }

  void operator()(const ProgramEnd&) const {}

  void operator()(const PathMode& m) const {
    out << ",\"mode\":\"" << path_mode_code(m.mode) << '"';
    if (m.mode != PathMode::Mode::Blend) return;
    out << ",\"p\":";
    out.num(m.tolerance);
    out << ",\"q\":";
    out.num(m.naive_cam);
  }

  void operator()(const MachineCode& m) const {
    out << ",\"code\":\"" << m.letter;
    out.integer(m.code);
    out << '"';
    optional_num(out, ",\"p\":", m.p);
    optional_num(out, ",\"q\":", m.q);
  }
};

}  // namespace

void append_jsonl(fmt::memory_buffer& buf, const Op& op, std::string_view file) {
  Out out(buf);
  out << "{\"op\":\"" << op_name(op.kind) << "\",\"src\":[";
  out.integer(op.src.line);
  out << ',';
  out.integer(op.src.col);
  out << ']';
  if (!file.empty()) {
    out << ",\"file\":";
    json_string(out, file);
  }
  std::visit(JsonFields{out}, op.kind);
  out << '}';
}

}  // namespace usina::canon
