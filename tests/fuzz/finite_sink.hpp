// What the fuzz targets that make a canon stream share: a sink that
// discards it after checking that each move's numbers are finite (a NaN
// reaching a post would be written to a part program).
#pragma once

#include <cmath>
#include <variant>

#include "canon/sink.hpp"
#include "core/vec3.hpp"

namespace usina::fuzz {

class FiniteSink final : public canon::Sink {
 public:
  void on(const canon::Op& op) override {
    if (const auto* t = std::get_if<canon::Traverse>(&op.kind)) check(t->to);
    if (const auto* f = std::get_if<canon::Feed>(&op.kind)) {
      check(f->to);
      if (f->f && !std::isfinite(*f->f)) __builtin_trap();
    }
    if (const auto* a = std::get_if<canon::Arc>(&op.kind)) {
      check(a->to);
      check(a->center);
      check(a->normal);
    }
  }

 private:
  static void check(const core::Vec3& v) {
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) __builtin_trap();
  }
};

}  // namespace usina::fuzz
