// Trace writers: the JSONL of spec/trace.md and a human-readable text form.
#pragma once

#include <cstdio>

#include <fmt/format.h>

#include "canon/sink.hpp"
#include "core/source.hpp"

namespace usina::canon {

enum class TraceFormat { Jsonl, Text };

class TraceWriter final : public Sink {
 public:
  TraceWriter(std::FILE* out, TraceFormat format) : out_(out), format_(format) {}

  TraceWriter(const TraceWriter&) = delete;
  TraceWriter& operator=(const TraceWriter&) = delete;
  ~TraceWriter() override;

  void on(const Op& op) override;
  void finish() override;

  // Names the file of ops that come from another file than the program's
  // (subroutine files): JSONL adds "file", text prefixes the name.
  void set_sources(const core::SourceManager* sources) { sources_ = sources; }

 private:
  std::string_view file_of(const Op& op) const;
  void flush_if_full();
  std::FILE* out_;
  TraceFormat format_;
  const core::SourceManager* sources_ = nullptr;
  fmt::memory_buffer buf_;
};

// One op as its JSONL line, without the newline (tests, the web API).
std::string to_jsonl(const Op& op);

}  // namespace usina::canon
