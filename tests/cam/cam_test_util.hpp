// Helpers for the cam tests: walking a retained op stream.
#pragma once

#include <vector>

#include "canon/toolpath.hpp"

namespace usina::cam::testing {

template <typename T>
std::vector<T> ops_of(const canon::Toolpath& tp) {
  std::vector<T> out;
  for (const canon::Op& op : tp.ops()) {
    if (const T* t = std::get_if<T>(&op.kind)) out.push_back(*t);
  }
  return out;
}

// The end point of a motion op (traverse, feed, arc), or nullopt.
inline std::optional<core::Vec3> end_of(const canon::Op& op) {
  if (const auto* t = std::get_if<canon::Traverse>(&op.kind)) return t->to;
  if (const auto* f = std::get_if<canon::Feed>(&op.kind)) return f->to;
  if (const auto* a = std::get_if<canon::Arc>(&op.kind)) return a->to;
  return std::nullopt;
}

inline int count_code(const core::DiagnosticList& d, core::Code code) {
  int n = 0;
  for (const auto& x : d.all())
    n += x.code == code ? 1 : 0;
  return n;
}

}  // namespace usina::cam::testing
