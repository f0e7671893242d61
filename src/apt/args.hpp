// Reads the arguments of a statement after its slash, and expressions:
// numbers with + - * / ** and the APT functions (angles in degrees), scalar
// and geometry names, minor words, nested definitions "(POINT/1,2)" and
// "(P2=POINT/1,3)". An error is reported at its token; the reader then
// answers false and the statement is dropped.
#pragma once

#include <optional>
#include <vector>

#include "apt/lexer.hpp"
#include "apt/symbols.hpp"

namespace usina::apt {

class ArgReader {
 public:
  // `pattern_points`: the points the program's patterns hold so far.
  ArgReader(const std::vector<Token>& toks, std::size_t pos, SymbolTable& symbols,
            std::vector<Definition>& defs, double zsurf, core::DiagnosticSink& diags,
            std::size_t& pattern_points)
      : toks_(toks),
        pos_(pos),
        symbols_(symbols),
        defs_(defs),
        zsurf_(zsurf),
        diags_(diags),
        pattern_points_(pattern_points) {}

  // The comma-separated arguments to the end of the statement (or a ')').
  // `any_word`: a word that names nothing is taken as a word (MACHIN/name).
  std::optional<std::vector<Arg>> arguments(bool any_word = false);

  // One expression (a scalar assignment's right side), to the end.
  std::optional<double> whole_expression();

  // A definition `MAJOR / args` from the current token on, to `stop` (")"
  // or the end), its geometry.
  std::optional<Geom> definition(bool nested);

 private:
  const Token& at() const { return toks_[pos_]; }

  bool is(const char* punct) const { return at().kind == TokKind::Punct && at().text == punct; }

  bool fail(const Token& t, core::Code code, std::string message);
  std::optional<Arg> argument();
  std::optional<Arg> nested();
  std::optional<Arg> nested_definition();
  std::optional<double> expression();
  std::optional<double> sum();
  bool deeper(const Token& t);
  std::optional<double> term();
  std::optional<double> factor();
  std::optional<double> primary();
  std::optional<double> call(const Token& name);
  bool finite(const Token& t, double v, const char* what);

  const std::vector<Token>& toks_;
  std::size_t pos_;
  SymbolTable& symbols_;
  std::vector<Definition>& defs_;
  double zsurf_;
  bool any_word_ = false;
  int depth_ = 0;  // nesting of parentheses, powers and definitions
  core::DiagnosticSink& diags_;
  std::size_t& pattern_points_;
};

// Whether `w` is a geometry major word (POINT, LINE, CIRCLE, PLANE, VECTOR).
bool is_geometry_word(std::string_view w);

// Whether `w` is a minor word the processor knows.
bool is_minor_word(std::string_view w);

}  // namespace usina::apt
