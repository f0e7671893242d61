// Tool, spindle and coolant words, each written when it changes.
#include <cmath>

#include <fmt/format.h>

#include "post/writer.hpp"

namespace usina::post {

void Writer::tool_change(const canon::ToolChange& t) {
  cancel_cycle();
  std::string note;
  if (t.diameter) note = out_.comment(fmt::format("tool {} d{:g}", t.tool, *t.diameter));
  if (!control_.tool_change_m6 && !options_.tool_change) {
    // grbl has no tool changer: the operator changes the tool at a pause.
    out_.block(out_.comment(fmt::format("change to tool {}", t.tool)));
    out_.block(code('M', 0));
    return;
  }
  std::string w = fmt::format("T{} {}", t.tool, code('M', 6));
  if (control_.semicolon_comments) {
    w += note;  // ROMI reads the tool's diameter from this comment ("d10")
  } else if (!note.empty()) {
    out_.block(note);
  }
  out_.block(w);
}

void Writer::spindle(const canon::Spindle& s) {
  std::string w;
  if (s.dir != canon::SpindleDir::Off && speed_ != std::lround(s.rpm)) {
    speed_ = std::lround(s.rpm);
    w = fmt::format("S{}", std::lround(s.rpm));  // a whole number: Fanuc rejects "S3000."
  }
  if (s.dir != dir_) {
    dir_ = s.dir;
    spindle_stop_written_ = s.dir == canon::SpindleDir::Off;
    append(w, code('M',
                   s.dir == canon::SpindleDir::Cw ? 3 : (s.dir == canon::SpindleDir::Ccw ? 4 : 5)));
  }
  if (!w.empty()) out_.block(w);
}

void Writer::coolant(const canon::Coolant& c) {
  // M9 turns both off; M7 and M8 each turn one on.
  if ((coolant_.mist && !c.mist) || (coolant_.flood && !c.flood)) {
    out_.block(code('M', 9));
    coolant_ = {};
    coolant_off_written_ = true;
  }
  if (c.mist && !coolant_.mist) out_.block(code('M', 7));
  if (c.flood && !coolant_.flood) out_.block(code('M', 8));
  if (c.mist || c.flood) coolant_off_written_ = false;
  coolant_ = c;
}

}  // namespace usina::post
