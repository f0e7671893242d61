// usina gen: generators that write programs a control cannot express itself
// (seed 002: the elliptical pocket; seed 004 table 7.5: pockets, profiles,
// drilling, engraving). One file per generator, each registering its
// subcommand on the `gen` app with add_gen_<name>(gen).
#pragma once

#include <CLI/CLI.hpp>

namespace usina::cli {

void add_gen_ellipse(CLI::App& gen);

}  // namespace usina::cli
