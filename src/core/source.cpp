#include "core/source.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include <sys/mman.h>
#include <sys/stat.h>

namespace usina::core {
namespace {

constexpr std::uint64_t kReleaseChunk = 8u << 20;  // release in 8 MiB steps

std::uint64_t page_size() {
  static const auto size = static_cast<std::uint64_t>(sysconf(_SC_PAGESIZE));
  return size;
}

}  // namespace

std::unique_ptr<SourceFile> SourceFile::open(const std::string& path, std::string& error) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) {
    error = std::strerror(errno);
    return nullptr;
  }

  struct stat st {};

  if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    error = S_ISDIR(st.st_mode) ? "is a directory" : "not a regular file";
    ::close(fd);
    return nullptr;
  }
  std::unique_ptr<SourceFile> f(new SourceFile());
  f->name_ = path;
  const auto len = static_cast<std::size_t>(st.st_size);
  if (len > 0) {
    void* p = mmap(nullptr, len, PROT_READ, MAP_PRIVATE, fd, 0);
    if (p == MAP_FAILED) {
      error = std::strerror(errno);
      ::close(fd);
      return nullptr;
    }
    madvise(p, len, MADV_SEQUENTIAL);
    f->map_ = p;
    f->map_len_ = len;
    f->text_ = std::string_view(static_cast<const char*>(p), len);
  }
  ::close(fd);
  return f;
}

std::unique_ptr<SourceFile> SourceFile::from_string(std::string name, std::string text) {
  std::unique_ptr<SourceFile> f(new SourceFile());
  f->name_ = std::move(name);
  f->owned_ = std::move(text);
  f->text_ = f->owned_;
  return f;
}

SourceFile::~SourceFile() {
  if (map_ != nullptr) munmap(map_, map_len_);
}

std::string_view SourceFile::line_at(std::uint64_t offset) const {
  if (offset >= text_.size()) return {};
  const std::string_view rest = text_.substr(offset);
  std::size_t end = rest.find('\n');
  if (end == std::string_view::npos) end = rest.size();
  std::string_view line = rest.substr(0, end);
  while (!line.empty() && line.back() == '\r')
    line.remove_suffix(1);
  return line;
}

void SourceFile::release_before(std::uint64_t offset) {
  if (map_ == nullptr || offset < released_ + kReleaseChunk) return;
  const std::uint64_t end = offset / page_size() * page_size();
  char* base = static_cast<char*>(map_);
  madvise(base + released_, end - released_, MADV_DONTNEED);
  released_ = end;
}

std::uint32_t SourceManager::add(std::unique_ptr<SourceFile> file) {
  files_.push_back(std::move(file));
  return static_cast<std::uint32_t>(files_.size() - 1);
}

const SourceFile* SourceManager::get(std::uint32_t id) const {
  return id < files_.size() ? files_[id].get() : nullptr;
}

SourceFile* SourceManager::get(std::uint32_t id) {
  return id < files_.size() ? files_[id].get() : nullptr;
}

std::string render(const Diagnostic& d, const SourceManager& sources) {
  std::string out;
  const SourceFile* file = sources.get(d.loc.file);
  out += file != nullptr ? file->name() : std::string("<input>");
  if (d.loc.line > 0) {
    out += ':' + std::to_string(d.loc.line);
    if (d.loc.col > 0) out += ':' + std::to_string(d.loc.col);
  }
  out += ": ";
  out += severity_name(d.severity);
  out += ": ";
  out += d.message;
  out += " [";
  out += code_name(d.code);
  out += "]\n";
  if (file == nullptr || d.loc.line == 0) return out;
  const std::string_view line = file->line_at(d.loc.line_offset);
  out += "  ";
  out += line;
  out += '\n';
  if (d.loc.col > 0) {
    out += "  ";
    for (std::uint32_t i = 1; i < d.loc.col && i - 1 < line.size(); ++i) {
      out += line[i - 1] == '\t' ? '\t' : ' ';
    }
    out += '^';
    for (std::uint32_t i = 1; i < d.loc.length; ++i)
      out += '~';
    out += '\n';
  }
  return out;
}

}  // namespace usina::core
