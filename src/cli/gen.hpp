// usina gen: generators that write programs a control cannot express itself
// (seed 002: the elliptical pocket; seed 004 table 7.5: pockets, profiles,
// drilling, engraving). One file per generator, each registering its
// subcommand on the `gen` app with add_gen_<name>(gen) (declared here,
// called in gen.cpp). A generator adds its own options, then
// add_post_options (cli/post_output.hpp) for --post, -o and the post's
// options; its callback checks the input (exit 2 and
// "usina: error: <generator>: ..." on stderr) and calls write_program with a
// function that emits the canon ops into the sink it is given.
#pragma once

#include <CLI/CLI.hpp>

namespace usina::cli {

void add_gen_ellipse(CLI::App& gen);
void add_gen_from_dxf(CLI::App& gen);
void add_gen_pocket(CLI::App& gen);
void add_gen_profile(CLI::App& gen);
void add_gen_drill(CLI::App& gen);
void add_gen_engrave(CLI::App& gen);

}  // namespace usina::cli
