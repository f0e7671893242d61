// What every usina executable does around its work (usina, usina-serve):
// standard output through core::OutputFile, so a full disk is an error and
// not a success, and no exception leaves main.
#pragma once

namespace usina::cli {

// The exit status of a usage error, an unreadable input or an unwritable output.
inline constexpr int kUsageStatus = 2;

// Runs `run(argc, argv)` with standard output checked at the end: its
// status, or 2 when the output or the run failed (said on standard error).
int run_guarded(int argc, char** argv, int (*run)(int, char**));

}  // namespace usina::cli
