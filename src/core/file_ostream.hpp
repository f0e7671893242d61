// A std::ostream onto a C stream, so code that writes to an ostream (the
// posts) can write through an OutputFile; errors stay in the FILE, where
// OutputFile::commit() sees them.
#pragma once

#include <cstdio>
#include <ostream>
#include <streambuf>

namespace usina::core {

class FileStreamBuf final : public std::streambuf {
 public:
  explicit FileStreamBuf(std::FILE* file) : file_(file) {}

 protected:
  int_type overflow(int_type c) override {
    if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
    return std::fputc(c, file_) == EOF ? traits_type::eof() : c;
  }

  std::streamsize xsputn(const char* s, std::streamsize n) override {
    return static_cast<std::streamsize>(std::fwrite(s, 1, static_cast<std::size_t>(n), file_));
  }

  int sync() override { return std::fflush(file_) == 0 ? 0 : -1; }

 private:
  std::FILE* file_;
};

class FileOstream final : public std::ostream {
 public:
  explicit FileOstream(std::FILE* file) : std::ostream(nullptr), buf_(file) { rdbuf(&buf_); }

 private:
  FileStreamBuf buf_;
};

}  // namespace usina::core
