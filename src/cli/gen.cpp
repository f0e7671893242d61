// usina gen <generator>: the frame; every generator adds its own subcommand.
#include "cli/gen.hpp"

#include "cli/verbs.hpp"

namespace usina::cli {

void add_gen(CLI::App& app) {
  CLI::App* gen = app.add_subcommand("gen", "generate a program: a cycle the control lacks");
  gen->require_subcommand(1);
  add_gen_ellipse(*gen);
  add_gen_from_dxf(*gen);
  add_gen_pocket(*gen);
  add_gen_profile(*gen);
  add_gen_drill(*gen);
  add_gen_engrave(*gen);
}

}  // namespace usina::cli
