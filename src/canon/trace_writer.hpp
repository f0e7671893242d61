// Trace writers: the JSONL of spec/trace.md and a human-readable text form.
#pragma once

#include <cstdio>

#include <fmt/format.h>

#include "canon/sink.hpp"

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

 private:
  void flush_if_full();
  std::FILE* out_;
  TraceFormat format_;
  fmt::memory_buffer buf_;
};

// One op as its JSONL line, without the newline (tests, the web API).
std::string to_jsonl(const Op& op);

}  // namespace usina::canon
