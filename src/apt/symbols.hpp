// The names a part program defines: scalars and geometry.
#pragma once

#include <string>
#include <unordered_map>

#include "apt/geometry.hpp"

namespace usina::apt {

struct Symbol {
  bool scalar = false;
  double value = 0.0;
  Geom geom;
};

using SymbolTable = std::unordered_map<std::string, Symbol>;

// A geometry definition as the processor made it, in program order.
struct Definition {
  std::string name;
  Geom geom;
  core::SourceLoc loc;
};

}  // namespace usina::apt
