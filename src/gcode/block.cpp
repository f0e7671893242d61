#include "gcode/block.hpp"

namespace usina::gcode {

const char* okind_name(OKind k) {
  switch (k) {
  case OKind::Sub: return "sub";
  case OKind::EndSub: return "endsub";
  case OKind::Call: return "call";
  case OKind::Return: return "return";
  case OKind::If: return "if";
  case OKind::ElseIf: return "elseif";
  case OKind::Else: return "else";
  case OKind::EndIf: return "endif";
  case OKind::While: return "while";
  case OKind::EndWhile: return "endwhile";
  case OKind::Do: return "do";
  case OKind::Repeat: return "repeat";
  case OKind::EndRepeat: return "endrepeat";
  case OKind::Break: return "break";
  case OKind::Continue: return "continue";
  case OKind::Program: return "program";
  }
  return "?";
}

void Block::clear() {
  loc = {};
  deleted = false;
  percent = false;
  line_number.reset();
  words.clear();
  assigns.clear();
  comments.clear();
  o.reset();
  exprs.clear();
}

}  // namespace usina::gcode
