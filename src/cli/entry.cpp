#include "cli/entry.hpp"

#include <cstdio>
#include <exception>
#include <new>
#include <system_error>

#include <fmt/format.h>

#include "core/output_file.hpp"

namespace usina::cli {
namespace {

// Everything written to standard output reached it, or the run failed: a
// full disk must never look like success.
int close_stdout(core::OutputFile& out, int status) {
  if (auto done = out.commit(); !done) {
    fmt::print(stderr, "usina: error: {}\n", done.error());
    return kUsageStatus;
  }
  return status;
}

}  // namespace

int run_guarded(int argc, char** argv, int (*run)(int, char**)) {
  auto out = core::OutputFile::standard_output();
  if (!out) {
    fmt::print(stderr, "usina: error: {}\n", out.error());
    return kUsageStatus;
  }
  stdout = out->stream();  // glibc's stdout is a variable: every print goes through `out`
  int status = kUsageStatus;
  try {
    status = run(argc, argv);
  } catch (const std::bad_alloc&) {
    std::fputs("usina: error: out of memory\n", stderr);
  } catch (const std::system_error& e) {
    // fmt::print throws when standard output fails; commit says why.
    if (std::ferror(stdout) == 0) fmt::print(stderr, "usina: error: {}\n", e.what());
  } catch (const std::exception& e) {
    fmt::print(stderr, "usina: error: {}\n", e.what());
  }
  return close_stdout(*out, status);
}

}  // namespace usina::cli
