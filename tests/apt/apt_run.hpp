// Runs the APT processor on program text (the apt tests' helper).
#pragma once

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "apt/processor.hpp"
#include "core/diagnostic.hpp"

namespace usina::apt::test {

struct AptRun {
  AptResult result;
  core::DiagnosticList diags;

  // The definition named `name`; fails the test when there is none.
  Geom def(const std::string& name) const {
    for (const Definition& d : result.definitions)
      if (d.name == name) return d.geom;
    ADD_FAILURE() << "no definition " << name;
    return {};
  }

  bool has(core::Code code) const {
    for (const core::Diagnostic& d : diags.all())
      if (d.code == code) return true;
    return false;
  }
};

inline AptRun run(const std::string& text) {
  AptRun r;
  r.result = process(text, 0, r.diags);
  return r;
}

// The canonical numbers expected; lines and planes compared up to sign
// (research/apt.md §4.1: the sign of a normal depends on the form).
inline void expect_canon(const Geom& g, std::vector<double> want, bool up_to_sign = false,
                         double tol = 1e-6) {
  double sign = 1.0;
  if (up_to_sign && g.c[0] * want[0] + g.c[1] * want[1] + g.c[2] * want[2] < 0) sign = -1.0;
  for (std::size_t i = 0; i < want.size(); ++i)
    EXPECT_NEAR(sign * g.c[i], want[i], tol) << "canonical number " << i;
}

}  // namespace usina::apt::test
