// The APT functions of an expression: SINF, COSF, ... (angles in degrees).
#include <cmath>
#include <numbers>

#include "apt/args.hpp"

namespace usina::apt {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

struct Function {
  std::string_view name;
  std::size_t arity;
  double (*fn)(const std::vector<double>&);
  bool (*domain)(const std::vector<double>&);  // null: every value
};

bool any(const std::vector<double>&) {
  return true;
}

bool non_negative(const std::vector<double>& a) {
  return a[0] >= 0.0;
}

bool positive(const std::vector<double>& a) {
  return a[0] > 0.0;
}

bool unit(const std::vector<double>& a) {
  return a[0] >= -1.0 && a[0] <= 1.0;
}

bool not_origin(const std::vector<double>& a) {
  return a[0] != 0.0 || a[1] != 0.0;
}

const Function kFunctions[] = {
    {"SINF", 1, [](const std::vector<double>& a) { return std::sin(a[0] * kDeg); }, any},
    {"COSF", 1, [](const std::vector<double>& a) { return std::cos(a[0] * kDeg); }, any},
    {"TANF", 1, [](const std::vector<double>& a) { return std::tan(a[0] * kDeg); }, any},
    {"ASINF", 1, [](const std::vector<double>& a) { return std::asin(a[0]) / kDeg; }, unit},
    {"ACOSF", 1, [](const std::vector<double>& a) { return std::acos(a[0]) / kDeg; }, unit},
    {"ATANF", 1, [](const std::vector<double>& a) { return std::atan(a[0]) / kDeg; }, any},
    {"ATAN2F", 2, [](const std::vector<double>& a) { return std::atan2(a[0], a[1]) / kDeg; },
     not_origin},
    {"SQRTF", 1, [](const std::vector<double>& a) { return std::sqrt(a[0]); }, non_negative},
    {"ABSF", 1, [](const std::vector<double>& a) { return std::fabs(a[0]); }, any},
    {"EXPF", 1, [](const std::vector<double>& a) { return std::exp(a[0]); }, any},
    {"LOGF", 1, [](const std::vector<double>& a) { return std::log(a[0]); }, positive},
    {"LOG10F", 1, [](const std::vector<double>& a) { return std::log10(a[0]); }, positive},
    {"INTF", 1, [](const std::vector<double>& a) { return std::trunc(a[0]); }, any},
    {"SIGNF", 2, [](const std::vector<double>& a) { return std::copysign(std::fabs(a[0]), a[1]); },
     any},
    {"MAXF", 2, [](const std::vector<double>& a) { return std::max(a[0], a[1]); }, any},
    {"MINF", 2, [](const std::vector<double>& a) { return std::min(a[0], a[1]); }, any},
};

}  // namespace

std::optional<double> ArgReader::call(const Token& name) {
  const Function* f = nullptr;
  for (const Function& cand : kFunctions)
    if (cand.name == name.text) f = &cand;
  if (f == nullptr) {
    const bool geometric = name.text == "DISTF" || name.text == "DOTF" || name.text == "ANGLF";
    fail(name, geometric ? core::Code::AptNotSupported : core::Code::AptUndefinedSymbol,
         geometric ? "usina's APT does not compute " + name.text + " yet"
                   : name.text +
                         " is not an APT function (SINF, COSF, TANF, ASINF, ACOSF, "
                         "ATANF, ATAN2F, SQRTF, ABSF, EXPF, LOGF, LOG10F, INTF, SIGNF, "
                         "MAXF, MINF)");
    return std::nullopt;
  }
  ++pos_;  // (
  std::vector<double> args;
  for (;;) {
    auto v = expression();
    if (!v) return std::nullopt;
    args.push_back(*v);
    if (!is(",")) break;
    ++pos_;
  }
  if (!is(")")) {
    fail(at(), core::Code::AptSyntax, "expected ')' to close " + name.text + "(");
    return std::nullopt;
  }
  ++pos_;
  if (args.size() != f->arity) {
    fail(name, core::Code::AptBadArgument,
         name.text + " takes " + std::to_string(f->arity) + " argument(s), not " +
             std::to_string(args.size()));
    return std::nullopt;
  }
  if (!f->domain(args)) {
    fail(name, core::Code::AptArithmetic,
         name.text + " is undefined for " + std::to_string(args[0]) + " (outside its domain)");
    return std::nullopt;
  }
  const double v = f->fn(args);
  if (!finite(name, v, name.text.c_str())) return std::nullopt;
  return v;
}

}  // namespace usina::apt
