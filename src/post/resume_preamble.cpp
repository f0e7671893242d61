// The restart preamble in a control's own blocks (resume_preamble.hpp).
#include "post/resume_preamble.hpp"

#include <sstream>

#include <fmt/format.h>

#include "post/block_out.hpp"
#include "post/control.hpp"

namespace usina::post {
namespace {

std::optional<Control> control_named(std::string_view name) {
  if (name == "rs274ngc") return rs274ngc_control();
  if (name == "fanuc") return fanuc_control();
  if (name == "grbl") return grbl_control();
  if (name == "romi") return romi_control();
  return std::nullopt;
}

// "G1" or "G01"; "G59.1" from tenths.
std::string code(const Control& c, char letter, int tenths) {
  if (tenths % 10 != 0) return fmt::format("{}{}.{}", letter, tenths / 10, tenths % 10);
  return c.two_digit_codes ? fmt::format("{}{:02}", letter, tenths / 10)
                           : fmt::format("{}{}", letter, tenths / 10);
}

void add(std::string& words, const std::string& w) {
  if (!words.empty()) words += ' ';
  words += w;
}

std::string title(const canon::ResumeState& s) {
  std::string t = fmt::format("restart at line {}", s.line);
  if (s.n_word) t += fmt::format(" block N{}", *s.n_word);
  if (s.by_tool) t += fmt::format(" first change to tool {}", *s.by_tool);
  return t;
}

void modes(BlockOut& out, const Control& c, const canon::ResumeState& s) {
  const bool romi = c.name == "romi";
  std::string w;
  add(w, code(c, 'G', romi ? (s.inch ? 700 : 710) : (s.inch ? 200 : 210)));
  add(w, code(c, 'G', s.plane * 10));
  add(w, code(c, 'G', 900));
  add(w, code(c, 'G', 400));
  if (!romi) add(w, code(c, 'G', 800));
  if (s.work_offset != 0) add(w, code(c, 'G', s.work_offset));
  if (c.per_revolution || s.feed_mode != 95)
    if (!romi) add(w, code(c, 'G', s.feed_mode * 10));
  out.block(w);
}

void tool_spindle_coolant(BlockOut& out, const Control& c, const canon::ResumeState& s) {
  if (s.tool && !s.start_block_changes_tool) {
    if (c.tool_change_m6 && c.name == "romi" && s.tool_diameter_mm) {
      // Romi's reader takes the tool's diameter from its change's comment
      // ("T01 M06;fresa d10"): without it the restart is not read back.
      out.block(fmt::format("T{} {}{}", *s.tool, code(c, 'M', 60),
                            out.comment(fmt::format("d{:g}", *s.tool_diameter_mm))));
    } else if (c.tool_change_m6) {
      out.block(fmt::format("T{} {}", *s.tool, code(c, 'M', 60)));
    } else {
      out.block(out.comment(fmt::format("change to tool {}", *s.tool)));
      out.block(code(c, 'M', 0));
    }
  }
  if (s.spindle != canon::SpindleDir::Off) {
    // S is a whole rpm on every control (Fanuc's "S1200." is not its form)
    std::string w = fmt::format("S{:g}", s.rpm);
    add(w, code(c, 'M', s.spindle == canon::SpindleDir::Cw ? 30 : 40));
    out.block(w);
  }
  if (s.coolant.mist) out.block(code(c, 'M', 70));
  if (s.coolant.flood) out.block(code(c, 'M', 80));
}

void approach(BlockOut& out, const Control& c, const canon::ResumeState& s) {
  std::string w = code(c, 'G', 0);
  if (s.length_offset) add(w, code(c, 'G', 430));
  out.append_word(w, 'Z', s.safe_z);
  if (s.length_offset) add(w, fmt::format("H{}", *s.length_offset));
  out.block(w);
  w = code(c, 'G', 0);
  out.append_word(w, 'X', s.start.x);
  out.append_word(w, 'Y', s.start.y);
  out.block(w);
  if (out.rounded(s.start.z) < out.rounded(s.safe_z)) {
    w = code(c, 'G', 10);
    out.append_word(w, 'Z', s.start.z);
    if (s.feed) out.append_word(w, 'F', *s.feed);
    out.block(w);
  }
}

}  // namespace

tl::expected<std::string, std::string> resume_preamble(std::string_view control,
                                                       const canon::ResumeState& s) {
  const auto c = control_named(control);
  if (!c) {
    return tl::unexpected(fmt::format(
        "usina has no post for dialect {}: it cannot write the restart's preamble", control));
  }
  std::ostringstream text;
  {
    BlockOut out(text, *c, false);
    out.block(out.comment(title(s)));
    modes(out, *c, s);
    tool_spindle_coolant(out, *c, s);
    if (s.moved) {
      approach(out, *c, s);
    } else if (s.length_offset) {
      out.block(fmt::format("{} H{}", code(*c, 'G', 430), *s.length_offset));
    }
    if (!s.block_has_motion) out.block(code(*c, 'G', s.motion));
    if (s.feed && !s.moved) {
      std::string w;
      out.append_word(w, 'F', *s.feed);
      out.block(w);
    }
    if (s.incremental) out.block(code(*c, 'G', 910));
  }
  return text.str();
}

}  // namespace usina::post
