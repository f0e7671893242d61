// A block after step 1 (evaluation): what a dialect's front end hands the
// interpreter, which runs steps 2-4 on it (DESIGN.md, "One road below the
// text"; docs/dialects.md, "How dialects are built"). A front end reads its
// own syntax (macro statements, block ends, lower-case increments, polar
// words), evaluates every value, and gives the interpreter numbers with the
// places the user wrote them at; it never writes G-code text for the
// interpreter to read again. From here on the road is the same for every
// dialect: rs274ngc's own reader, fanuc, grbl and romi hand it to the
// RS274NGC interpreter (romi through its handlers, romi/translate.hpp, which
// work its own forms into these words first); the front ends to come hand
// it over too.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>

#include "core/diagnostic.hpp"
#include "gcode/block.hpp"

namespace usina::gcode {

// One word: its letter, its value, and the column the user wrote it at.
struct EvaluatedWord {
  char letter = 0;  // 'A'..'Z' in upper case; '@' and '^' are LinuxCNC's polar words
  // G and M words carry the code as written (38.2 for G38.2): the
  // interpreter reads codes in tenths and refuses anything else.
  double value = 0.0;
  // The word's column in its line, where its diagnostics point; 0 for a
  // word the front end made (a dialect's cycle, a kept modal value): its
  // diagnostics point at the block.
  std::uint32_t col = 0;
  // Written as an increment whatever G90/G91 say (romi's lower-case words,
  // docs/romi.md): the word counts from where its move starts. Romi's
  // handlers resolve their own; the interpreter takes it on the axis words
  // of a move to a point (G0-G3, G33, G38, splines, G28/G30's point) and
  // refuses it elsewhere.
  bool incremental = false;
};

// An RS274NGC parameter assignment with its value read (RS274NGC 3.2.1:
// every value of a block is read before any assignment of the block takes
// effect). The front end has checked that the parameter may be written.
struct EvaluatedAssign {
  int index = 0;     // #index; 0 for a named parameter
  std::string name;  // #<name>, normalised (lower case, no blanks)
  double value = 0.0;
  std::uint32_t col = 0;
};

// One block, evaluated. Block delete ('/') is decided before evaluation,
// by the front end: a deleted block is neither evaluated nor handed over.
// Control flow (subroutines, loops, jumps) is the front end's too; M98 and
// M99 among the words run RS274NGC's Fanuc-style subprograms of the file
// Interpreter::run() reads, so a front end with its own subprograms takes
// them first.
struct EvaluatedBlock {
  // The block: file, line, column of its first character. Its operations
  // carry it, and so do its diagnostics where no word's column applies.
  core::SourceLoc loc;
  std::span<const EvaluatedWord> words;  // in the order written, G and M codes included
  // Applied once the words are sorted into modal groups, before the check.
  std::span<const EvaluatedAssign> assigns;
  // Comments become canon Comment operations; "(MSG, text)" is also an
  // operator message (N_MESSAGE). A front end whose control shows nothing
  // of its comments hands none.
  std::span<const CommentText> comments;

  bool empty() const { return words.empty() && assigns.empty() && comments.empty(); }
};

// A block that is one plain move, read by a front end (romi, fanuc, grbl)
// for Interpreter::run_plain_move: G0 or G1 (motion 0 or 10; -1, none: the
// motion in force), F and X Y Z as those words of a block would give them
// (program units; an axis left out stays).
struct PlainMove {
  static constexpr unsigned kF = 8;  // in `given` beside X (1), Y (2), Z (4)
  int motion = -1;
  unsigned given = 0;
  double f = 0.0;
  std::array<double, 3> xyz{};

  // One word of the move, whose letter is G, F, X, Y or Z (the front end
  // has checked it, and that it comes once): false for a G but G0 or G1.
  bool take(char letter, double value) {
    if (letter == 'G') {
      if (value != 0.0 && value != 1.0) return false;
      motion = value == 0.0 ? 0 : 10;
    } else if (letter == 'F') {
      f = value;
      given |= kF;
    } else {
      const auto axis = static_cast<unsigned>(letter - 'X');
      xyz[axis] = value;
      given |= 1u << axis;
    }
    return true;
  }
};

}  // namespace usina::gcode
