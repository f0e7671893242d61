#include "dnc/form_cycles.hpp"

#include <algorithm>
#include <sstream>

#include <fmt/format.h>

#include "dnc/form_reading.hpp"

namespace usina::dnc {
namespace {

constexpr cam::Range kFormMoves{1.0, kFormMaxMoves, true, "moves"};

using Reader = Reading (*)(FormFields&, post::PostOptions&);

struct Cycle {
  std::string_view name;
  Reader read;
};

constexpr Cycle kCycles[] = {
    {"ellipse_pocket", read_ellipse},      {"rect_pocket", read_rect_pocket},
    {"circle_pocket", read_circle_pocket}, {"drill_grid", read_drill_grid},
    {"bolt_circle", read_bolt_circle},     {"engrave", read_engrave},
    {"profile_dxf", read_profile_dxf},     {"pocket_dxf", read_pocket_dxf},
};

std::string read_dialect(FormFields& f) {
  std::string d = f.text("dialect", "the control", 20, std::nullopt);
  const auto& names = post::post_names();
  if (!d.empty() && std::find(names.begin(), names.end(), d) == names.end()) {
    f.fail("dialect", fmt::format("no control \"{}\"; give rs274ngc, fanuc, grbl or romi", d));
    d.clear();
  }
  return d;
}

// The generator into the dialect's post; every error to `out.errors`.
void write_program(const Reading& r, const post::PostOptions& options, FormProgram& out) {
  std::ostringstream text;
  FieldDiagnostics diags(r.phrases, r.work_field, r.other_field);
  auto post = post::make_post(out.dialect, text, options, diags);
  const bool made = post != nullptr && r.generate && r.generate(*post, diags);
  if (post) post->finish();
  out.errors = std::move(diags.errors);
  if (!made && out.errors.empty()) out.errors.push_back({"", "the cycle could not be made"});
  if (!out.errors.empty()) return;
  out.text = std::move(text).str();
  out.notes = std::move(diags.others);
}

}  // namespace

cam::Cutting read_cutting(FormFields& f) {
  cam::Cutting c;
  c.tool = f.whole("tool", "the tool number", 0, 99999, 1);
  c.tool_diameter = f.number("tool_diameter", "the tool diameter", cam::kToolDiameter, 6.0);
  c.feed = f.number("feed", "the feed", cam::kFeed, 600.0);
  c.plunge_feed = f.number("plunge_feed", "the plunge feed", cam::kFeed, 200.0);
  c.rpm = f.number("rpm", "the spindle speed", cam::kSpindle, 10000.0);
  c.safe_z = f.number("safe_z", "the safe Z", cam::kLength, 5.0);
  c.max_moves = f.number("max_moves", "the limit on moves", kFormMoves, kFormMaxMoves);
  return c;
}

cam::Vec2 read_point(FormFields& f, std::string_view x, std::string_view y, std::string_view what) {
  return {f.number(x, fmt::format("{}'s X", what), kCoordinate, 0.0),
          f.number(y, fmt::format("{}'s Y", what), kCoordinate, 0.0)};
}

const std::vector<std::string_view>& form_cycles() {
  static const std::vector<std::string_view> names = [] {
    std::vector<std::string_view> v;
    for (const Cycle& c : kCycles)
      v.push_back(c.name);
    return v;
  }();
  return names;
}

bool is_form_cycle(std::string_view cycle) {
  const auto& names = form_cycles();
  return std::find(names.begin(), names.end(), cycle) != names.end();
}

namespace {

nlohmann::json spec_json(const FieldSpec& f) {
  nlohmann::json j{{"name", f.name},
                   {"what", f.what},
                   {"kind", f.kind},
                   {"unit", f.range.unit},
                   {"min", f.range.min},
                   {"max", f.range.max},
                   {"min_included", f.range.min_included}};
  if (f.number_default) j["default"] = *f.number_default;
  if (f.text_default) j["default"] = *f.text_default;
  if (!f.choices.empty()) j["choices"] = f.choices;
  return j;
}

}  // namespace

nlohmann::json form_specs() {
  nlohmann::json cycles = nlohmann::json::array();
  for (const Cycle& c : kCycles) {
    // The cycle's own reading, of an empty form: each field it asks for is
    // described as it is asked (the errors of the empty form are dropped).
    const nlohmann::json empty = nlohmann::json::object();
    FormFields f(empty);
    std::vector<FieldSpec> specs;
    f.describe_into(specs);
    post::PostOptions options;
    c.read(f, options);
    nlohmann::json fields = nlohmann::json::array();
    for (const FieldSpec& s : specs)
      fields.push_back(spec_json(s));
    cycles.push_back({{"name", c.name}, {"fields", std::move(fields)}});
  }
  return {{"cycles", std::move(cycles)}};
}

FormProgram form_program(std::string_view cycle, const nlohmann::json& body) {
  FormProgram out;
  const auto it = std::find_if(std::begin(kCycles), std::end(kCycles),
                               [&](const Cycle& c) { return c.name == cycle; });
  if (it == std::end(kCycles)) {
    out.errors.push_back({"", fmt::format("no cycle \"{}\"", cycle)});
    return out;
  }
  FormFields f(body);
  post::PostOptions options;
  out.dialect = read_dialect(f);
  options.program_number = f.whole("program_number", "the program number", 1, 9999, 1000);
  const Reading r = it->read(f, options);
  f.refuse_unknown({"machine_class"});
  if (!f.ok()) {
    out.errors = f.take_errors();
    return out;
  }
  write_program(r, options, out);
  return out;
}

}  // namespace usina::dnc
