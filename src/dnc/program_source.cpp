#include "dnc/program_source.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>

#include <fmt/format.h>

namespace usina::dnc {
namespace {

class StringSource final : public ProgramSource {
 public:
  explicit StringSource(std::string text) : text_(std::move(text)) {}

  std::size_t read(std::span<char> out) override {
    const std::size_t n = std::min(out.size(), text_.size() - at_);
    std::copy_n(text_.data() + at_, n, out.data());
    at_ += n;
    return n;
  }

  std::optional<std::uint64_t> size() const override { return text_.size(); }

 private:
  std::string text_;
  std::size_t at_ = 0;
};

class FileSource final : public ProgramSource {
 public:
  FileSource(std::FILE* f, std::string path, std::optional<std::uint64_t> size)
      : file_(f), path_(std::move(path)), size_(size) {}

  ~FileSource() override { std::fclose(file_); }

  FileSource(const FileSource&) = delete;
  FileSource& operator=(const FileSource&) = delete;

  std::size_t read(std::span<char> out) override {
    const std::size_t n = std::fread(out.data(), 1, out.size(), file_);
    if (n == 0 && std::ferror(file_) != 0 && error_.empty()) {
      error_ = fmt::format("cannot read {}: {}", path_, std::strerror(errno));
    }
    return n;
  }

  std::string error() const override { return error_; }

  std::optional<std::uint64_t> size() const override { return size_; }

 private:
  std::FILE* file_;
  std::string path_;
  std::optional<std::uint64_t> size_;
  std::string error_;
};

}  // namespace

std::unique_ptr<ProgramSource> string_source(std::string text) {
  return std::make_unique<StringSource>(std::move(text));
}

tl::expected<std::unique_ptr<ProgramSource>, std::string> file_source(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (f == nullptr) {
    return tl::make_unexpected(fmt::format("cannot open {}: {}", path, std::strerror(errno)));
  }
  std::optional<std::uint64_t> size;
  if (std::fseek(f, 0, SEEK_END) == 0) {
    const long end = std::ftell(f);
    if (end >= 0) size = static_cast<std::uint64_t>(end);
    std::rewind(f);
  }
  return std::make_unique<FileSource>(f, path, size);
}

}  // namespace usina::dnc
