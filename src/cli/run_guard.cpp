#include "cli/run_guard.hpp"

#include <unistd.h>

#include <cstdio>
#include <string_view>

namespace usina::cli {
namespace {

// The progress line on standard error: written over itself ('\r', then
// erase to the end of the line), so the terminal keeps one line of it.
void show_on_stderr(std::string_view text) {
  std::fputs("\r\x1b[K", stderr);
  std::fwrite(text.data(), 1, text.size(), stderr);
  std::fflush(stderr);
}

canon::ProgressSink::Show progress_output() {
  if (::isatty(STDERR_FILENO) == 0) return [](std::string_view) {};
  return show_on_stderr;
}

}  // namespace

RunGuard::RunGuard(canon::Sink& sink, core::DiagnosticSink& diags, std::uint64_t max_ops)
    : batch_(sink),
      // A sink that reads no ops (check) is passed them unbatched: nothing
      // to gain, a call a block to lose.
      budget_(sink.reads_ops() ? static_cast<canon::Sink&>(batch_) : sink, max_ops, diags_),
      progress_(budget_, progress_output(), max_ops),
      diags_(diags, batch_, progress_) {}

void RunGuard::Diagnostics::report(core::Diagnostic d) {
  batch_.flush();
  progress_.erase();
  next_.report(std::move(d));
}

}  // namespace usina::cli
