#include "canon/trace_writer.hpp"

#include <fmt/compile.h>

#include "canon/trace_json.hpp"
#include "core/text.hpp"

namespace usina::canon {
namespace {

// fmt's own appender and compiled formats: no format string parsed per op.
using Out = fmt::appender;

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
    fmt::format_to(out, FMT_COMPILE(" {} {:g} rpm"), spindle_dir_name(m.dir), m.rpm);
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
    fmt::format_to(out, FMT_COMPILE(" {}"), path_mode_code(m.mode));
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
  append_jsonl(buf, op);
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
  const std::string_view file = file_of(op);
  if (format_ == TraceFormat::Jsonl) {
    append_jsonl(buf_, op, file);
  } else {
    auto out = fmt::appender(buf_);
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
