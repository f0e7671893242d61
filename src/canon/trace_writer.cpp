#include "canon/trace_writer.hpp"

#include <cmath>
#include <iterator>

#include <fmt/compile.h>

#include "core/text.hpp"

namespace usina::canon {
namespace {

// fmt's own appender and compiled formats: no format string parsed per op.
using Out = fmt::appender;

// Writes `v` so that reading it back gives the same double; -0 as 0.
// Most coordinates are short decimals (12.345): when v is exactly the
// double nearest to n / 10^6 for an integer n, "n / 10^6" in decimal reads
// back as v, and writing it takes a few integer divisions instead of the
// shortest-representation search (the hot path of `usina trace`).
void num(Out out, double v) {
  if (v == 0.0) v = 0.0;
  constexpr double kScale = 1e6;
  if (std::fabs(v) < 1e9) {
    const long long n = std::llround(v * kScale);
    if (static_cast<double>(n) / kScale == v) {
      unsigned long long u =
          n < 0 ? static_cast<unsigned long long>(-n) : static_cast<unsigned long long>(n);
      if (n < 0) *out++ = '-';
      out = fmt::format_to(out, FMT_COMPILE("{}"), u / 1000000ULL);
      unsigned long long frac = u % 1000000ULL;
      if (frac != 0) {
        char digits[7] = {};
        for (int i = 5; i >= 0; --i) {
          digits[i] = static_cast<char>('0' + frac % 10);
          frac /= 10;
        }
        int len = 6;
        while (digits[len - 1] == '0')
          --len;
        *out++ = '.';
        for (int i = 0; i < len; ++i)
          *out++ = digits[i];
      }
      return;
    }
  }
  fmt::format_to(out, FMT_COMPILE("{}"), v);
}

const char* path_mode_name(PathMode::Mode m) {
  switch (m) {
  case PathMode::Mode::ExactPath: return "G61";
  case PathMode::Mode::ExactStop: return "G61.1";
  case PathMode::Mode::Blend: return "G64";
  }
  return "G64";
}

void vec(Out out, const Vec3& v) {
  fmt::format_to(out, FMT_COMPILE("["));
  num(out, v.x);
  fmt::format_to(out, FMT_COMPILE(","));
  num(out, v.y);
  fmt::format_to(out, FMT_COMPILE(","));
  num(out, v.z);
  fmt::format_to(out, FMT_COMPILE("]"));
}

void vec2(Out out, const Vec2& v) {
  fmt::format_to(out, FMT_COMPILE("["));
  num(out, v.x);
  fmt::format_to(out, FMT_COMPILE(","));
  num(out, v.y);
  fmt::format_to(out, FMT_COMPILE("]"));
}

void abc(Out out, const Abc& a) {
  if (a[0] == 0.0 && a[1] == 0.0 && a[2] == 0.0) return;
  fmt::format_to(out, FMT_COMPILE(",\"abc\":"));
  vec(out, {a[0], a[1], a[2]});
}

void feed(Out out, const std::optional<double>& f) {
  fmt::format_to(out, FMT_COMPILE(",\"f\":"));
  if (f) {
    num(out, *f);
  } else {
    fmt::format_to(out, FMT_COMPILE("null"));
  }
}

// A JSON string of program text. Valid UTF-8 is copied; a byte that is not
// is read as Latin-1 (ISO 8859-1, the encoding of older controls' files:
// "(caf\xe9)" becomes "café"), so the line is always valid JSON
// (spec/trace.md).
void json_string(Out out, std::string_view s) {
  fmt::format_to(out, FMT_COMPILE("\""));
  for (std::size_t i = 0; i < s.size();) {
    const char c = s[i];
    const auto u = static_cast<unsigned char>(c);
    const std::size_t n = core::utf8_sequence_at(s, i);
    if (c == '"' || c == '\\') {
      fmt::format_to(out, FMT_COMPILE("\\{}"), c);
    } else if (u < 0x20 || u == 0x7F || n == 0) {
      fmt::format_to(out, FMT_COMPILE("\\u{:04x}"), u);
    } else {
      for (std::size_t k = 0; k < n; ++k)
        *out++ = s[i + k];
      i += n;
      continue;
    }
    ++i;
  }
  fmt::format_to(out, FMT_COMPILE("\""));
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

// The text form's words for it: "bored", "bored, dwell 0.5 s" ...
const char* hole_cycle_words(HoleCycle c) {
  switch (c) {
  case HoleCycle::Bore: return "bored";
  case HoleCycle::BoreDwell: return "bored with a dwell";
  case HoleCycle::BoreStop: return "bored, spindle stopped";
  case HoleCycle::Drill: break;
  }
  return "drilled";
}

const char* dir_name(SpindleDir d) {
  switch (d) {
  case SpindleDir::Cw: return "cw";
  case SpindleDir::Ccw: return "ccw";
  case SpindleDir::Off: return "off";
  }
  return "off";
}

struct JsonFields {
  Out out;

  void operator()(const Traverse& m) const {
    fmt::format_to(out, FMT_COMPILE(",\"to\":"));
    vec(out, m.to);
    abc(out, m.abc);
  }

  void operator()(const Feed& m) const {
    fmt::format_to(out, FMT_COMPILE(",\"to\":"));
    vec(out, m.to);
    feed(out, m.f);
    abc(out, m.abc);
  }

  void operator()(const Arc& m) const {
    fmt::format_to(out, FMT_COMPILE(",\"to\":"));
    vec(out, m.to);
    fmt::format_to(out, FMT_COMPILE(",\"center\":"));
    vec(out, m.center);
    fmt::format_to(out, FMT_COMPILE(",\"normal\":"));
    vec(out, m.normal);
    fmt::format_to(out, FMT_COMPILE(",\"turn\":{}"), m.turn);
    feed(out, m.f);
    abc(out, m.abc);
  }

  void operator()(const Probe& m) const {
    fmt::format_to(out, FMT_COMPILE(",\"to\":"));
    vec(out, m.to);
    abc(out, m.abc);
  }

  void operator()(const Spline& m) const {
    fmt::format_to(out, FMT_COMPILE(",\"to\":"));
    vec(out, m.to);
    fmt::format_to(out, FMT_COMPILE(",\"points\":["));
    for (std::size_t i = 0; i < m.points.size(); ++i) {
      if (i > 0) fmt::format_to(out, FMT_COMPILE(","));
      vec(out, m.points[i]);
    }
    fmt::format_to(out, FMT_COMPILE("]"));
    feed(out, m.f);
  }

  void operator()(const Dwell& m) const {
    fmt::format_to(out, FMT_COMPILE(",\"s\":"));
    num(out, m.s);
  }

  void operator()(const ToolChange& m) const {
    fmt::format_to(out, FMT_COMPILE(",\"tool\":{},\"diameter\":"), m.tool);
    if (m.diameter) {
      num(out, *m.diameter);
    } else {
      fmt::format_to(out, FMT_COMPILE("null"));
    }
  }

  void operator()(const Spindle& m) const {
    fmt::format_to(out, FMT_COMPILE(",\"rpm\":"));
    num(out, m.rpm);
    fmt::format_to(out, FMT_COMPILE(",\"dir\":\"{}\""), dir_name(m.dir));
  }

  void operator()(const Coolant& m) const {
    fmt::format_to(out, FMT_COMPILE(",\"mist\":{},\"flood\":{}"), m.mist, m.flood);
  }

  void operator()(const Hole& m) const {
    fmt::format_to(out, FMT_COMPILE(",\"at\":"));
    vec(out, m.at);
    fmt::format_to(out, FMT_COMPILE(",\"diameter\":"));
    num(out, m.diameter);
    fmt::format_to(out, FMT_COMPILE(",\"depth\":"));
    num(out, m.depth);
    // Only a bore says so: every drilled hole's trace stays as it was.
    if (m.cycle != HoleCycle::Drill)
      fmt::format_to(out, FMT_COMPILE(",\"cycle\":\"{}\""), hole_cycle_name(m.cycle));
    if (m.f) {
      fmt::format_to(out, FMT_COMPILE(",\"f\":"));
      num(out, *m.f);
    }
    if (m.cycle == HoleCycle::BoreDwell) {
      fmt::format_to(out, FMT_COMPILE(",\"dwell\":"));
      num(out, m.dwell);
    }
  }

  void operator()(const Pocket& m) const {
    fmt::format_to(out, FMT_COMPILE(",\"outline\":{{\"start\":"));
    vec2(out, m.outline.start);
    fmt::format_to(out, FMT_COMPILE(",\"segs\":["));
    bool first = true;
    for (const OutlineSegment& s : m.outline.segs) {
      fmt::format_to(out, FMT_COMPILE("{}{{\"to\":"), first ? "" : ",");
      first = false;
      vec2(out, s.to);
      if (s.center) {
        fmt::format_to(out, FMT_COMPILE(",\"center\":"));
        vec2(out, *s.center);
        fmt::format_to(out, FMT_COMPILE(",\"turn\":{}"), s.turn);
      }
      fmt::format_to(out, FMT_COMPILE("}}"));
    }
    fmt::format_to(out, FMT_COMPILE("]}},\"depth\":"));
    num(out, m.depth);
  }

  void operator()(const Comment& m) const {
    fmt::format_to(out, FMT_COMPILE(",\"text\":"));
    json_string(out, m.text);
  }

  void operator()(const ProgramEnd&) const {}

  void operator()(const PathMode& m) const {
    fmt::format_to(out, FMT_COMPILE(",\"mode\":\"{}\""), path_mode_name(m.mode));
    if (m.mode != PathMode::Mode::Blend) return;
    fmt::format_to(out, FMT_COMPILE(",\"p\":"));
    num(out, m.tolerance);
    fmt::format_to(out, FMT_COMPILE(",\"q\":"));
    num(out, m.naive_cam);
  }

  void operator()(const MachineCode& m) const {
    fmt::format_to(out, FMT_COMPILE(",\"code\":\"{}{}\""), m.letter, m.code);
    if (m.p) {
      fmt::format_to(out, FMT_COMPILE(",\"p\":"));
      num(out, *m.p);
    }
    if (m.q) {
      fmt::format_to(out, FMT_COMPILE(",\"q\":"));
      num(out, *m.q);
    }
  }
};

void write_json(Out out, const Op& op, std::string_view file = {}) {
  fmt::format_to(out, FMT_COMPILE("{{\"op\":\"{}\",\"src\":[{},{}]"), op_name(op.kind), op.src.line,
                 op.src.col);
  if (!file.empty()) {
    fmt::format_to(out, FMT_COMPILE(",\"file\":"));
    json_string(out, file);
  }
  std::visit(JsonFields{out}, op.kind);
  fmt::format_to(out, FMT_COMPILE("}}"));
}

void xyz(Out out, const Vec3& v) {
  fmt::format_to(out, FMT_COMPILE(" X{:.4f} Y{:.4f} Z{:.4f}"), v.x, v.y, v.z);
}

struct TextFields {
  Out out;

  void operator()(const Traverse& m) const { xyz(out, m.to); }

  void operator()(const Feed& m) const {
    xyz(out, m.to);
    if (m.f) fmt::format_to(out, FMT_COMPILE(" F{:g}"), *m.f);
  }

  void operator()(const Arc& m) const {
    xyz(out, m.to);
    fmt::format_to(out, FMT_COMPILE(" about ({:.4f}, {:.4f}, {:.4f}) turn {}"), m.center.x,
                   m.center.y, m.center.z, m.turn);
    if (m.f) fmt::format_to(out, FMT_COMPILE(" F{:g}"), *m.f);
  }

  void operator()(const Probe& m) const { xyz(out, m.to); }

  void operator()(const Spline& m) const {
    xyz(out, m.to);
    fmt::format_to(out, FMT_COMPILE(" ({} points)"), m.points.size());
    if (m.f) fmt::format_to(out, FMT_COMPILE(" F{:g}"), *m.f);
  }

  void operator()(const Dwell& m) const { fmt::format_to(out, FMT_COMPILE(" {:g} s"), m.s); }

  void operator()(const ToolChange& m) const {
    fmt::format_to(out, FMT_COMPILE(" T{}"), m.tool);
    if (m.diameter) fmt::format_to(out, FMT_COMPILE(" diameter {:g} mm"), *m.diameter);
  }

  void operator()(const Spindle& m) const {
    fmt::format_to(out, FMT_COMPILE(" {} {:g} rpm"), dir_name(m.dir), m.rpm);
  }

  void operator()(const Coolant& m) const {
    fmt::format_to(out, FMT_COMPILE(" mist {} flood {}"), m.mist ? "on" : "off",
                   m.flood ? "on" : "off");
  }

  void operator()(const Hole& m) const {
    fmt::format_to(out, FMT_COMPILE(" at ({:.4f}, {:.4f}, {:.4f}) diameter {:g} depth {:g}"),
                   m.at.x, m.at.y, m.at.z, m.diameter, m.depth);
    if (m.cycle != HoleCycle::Drill)
      fmt::format_to(out, FMT_COMPILE(" {}"), hole_cycle_words(m.cycle));
    if (m.cycle == HoleCycle::BoreDwell) fmt::format_to(out, FMT_COMPILE(" {:g} s"), m.dwell);
    if (m.f) fmt::format_to(out, FMT_COMPILE(" feed {:g}"), *m.f);
  }

  void operator()(const Pocket& m) const {
    fmt::format_to(out, FMT_COMPILE(" {} segments, depth {:g}"), m.outline.segs.size(), m.depth);
  }

  void operator()(const Comment& m) const {
    fmt::format_to(out, FMT_COMPILE(" {}"), core::printable(m.text));
  }

  void operator()(const ProgramEnd&) const {}

  void operator()(const PathMode& m) const {
    fmt::format_to(out, FMT_COMPILE(" {}"), path_mode_name(m.mode));
    if (m.mode == PathMode::Mode::Blend) {
      fmt::format_to(out, FMT_COMPILE(" P{:g} Q{:g}"), m.tolerance, m.naive_cam);
    }
  }

  void operator()(const MachineCode& m) const {
    fmt::format_to(out, FMT_COMPILE(" {}{}"), m.letter, m.code);
    if (m.p) fmt::format_to(out, FMT_COMPILE(" P{:g}"), *m.p);
    if (m.q) fmt::format_to(out, FMT_COMPILE(" Q{:g}"), *m.q);
  }
};

}  // namespace

std::string to_jsonl(const Op& op) {
  fmt::memory_buffer buf;
  write_json(fmt::appender(buf), op);
  return fmt::to_string(buf);
}

TraceWriter::~TraceWriter() {
  finish();
}

std::string_view TraceWriter::file_of(const Op& op) const {
  if (sources_ == nullptr || op.src.file == 0) return {};
  const core::SourceFile* f = sources_->get(op.src.file);
  return f != nullptr ? std::string_view(f->name()) : std::string_view();
}

void TraceWriter::on(const Op& op) {
  auto out = fmt::appender(buf_);
  const std::string_view file = file_of(op);
  if (format_ == TraceFormat::Jsonl) {
    write_json(out, op, file);
  } else {
    if (!file.empty()) fmt::format_to(out, FMT_COMPILE("{}:"), core::printable(file));
    fmt::format_to(out, FMT_COMPILE("{:>5}:{:<3} {:<8}"), op.src.line, op.src.col,
                   op_name(op.kind));
    std::visit(TextFields{out}, op.kind);
  }
  buf_.push_back('\n');
  flush_if_full();
}

void TraceWriter::flush_if_full() {
  if (buf_.size() >= (64u << 10)) finish();
}

void TraceWriter::finish() {
  if (buf_.size() == 0) return;
  std::fwrite(buf_.data(), 1, buf_.size(), out_);
  buf_.clear();
  std::fflush(out_);
}

}  // namespace usina::canon
