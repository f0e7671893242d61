#include "canon/toolpath.hpp"

#include <algorithm>

namespace usina::canon {

void Bounds::add(const Vec3& p) {
  if (empty) {
    min = max = p;
    empty = false;
    return;
  }
  for (int i = 0; i < 3; ++i) {
    min[i] = std::min(min[i], p[i]);
    max[i] = std::max(max[i], p[i]);
  }
}

namespace {

struct EndOf {
  Bounds& b;

  void operator()(const Traverse& m) const { b.add(m.to); }

  void operator()(const Feed& m) const { b.add(m.to); }

  void operator()(const Arc& m) const { b.add(m.to); }

  void operator()(const Probe& m) const { b.add(m.to); }

  void operator()(const Spline& m) const {
    for (const Vec3& p : m.points)
      b.add(p);
  }

  template <typename T>
  void operator()(const T&) const {}
};

}  // namespace

void Toolpath::on(const Op& op) {
  std::visit(EndOf{bounds_}, op.kind);
  ops_.push_back(op);
}

}  // namespace usina::canon
