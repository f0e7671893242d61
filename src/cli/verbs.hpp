// The verbs of the usina command; each registers itself on the app.
#pragma once

#include <vector>

#include <CLI/CLI.hpp>

namespace usina::cli {

void add_trace(CLI::App& app);
void add_check(CLI::App& app);
void add_calc(CLI::App& app);
void add_stats(CLI::App& app);
void add_draw(CLI::App& app);
void add_convert(CLI::App& app);
void add_gen(CLI::App& app);
void add_serve(CLI::App& app);
void add_resume(CLI::App& app);
void add_apt(CLI::App& app);
void add_simulate(CLI::App& app);
void add_job(CLI::App& app);

// Runs the server executable usina-serve, found beside usina, in this
// process's place with `args` (what followed "serve"); returns only when it
// could not, with the status of that error (said on standard error).
int exec_serve(std::vector<char*> args);

// The status the chosen verb left.
int exit_status();
void set_exit_status(int status);

}  // namespace usina::cli
