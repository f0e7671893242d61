#include "core/source.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>

#include <sys/mman.h>
#include <sys/stat.h>

#include "core/text.hpp"

namespace usina::core {
namespace {

constexpr std::uint64_t kReleaseChunk = 8u << 20;  // release in 8 MiB steps

std::uint64_t page_size() {
  static const auto size = static_cast<std::uint64_t>(sysconf(_SC_PAGESIZE));
  return size;
}

}  // namespace

std::unique_ptr<SourceFile> SourceFile::open(const std::string& path, std::string& error,
                                             std::uint64_t max_stream_bytes) {
  // O_NONBLOCK: opening a FIFO nobody writes must not hang the run.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
  if (fd < 0) {
    error = std::strerror(errno);
    return nullptr;
  }
  auto f = open_descriptor(fd, path, error, max_stream_bytes);
  ::close(fd);
  return f;
}

std::unique_ptr<SourceFile> SourceFile::open_descriptor(int fd, std::string name,
                                                        std::string& error,
                                                        std::uint64_t max_stream_bytes) {
  struct stat st {};

  if (fstat(fd, &st) != 0) {
    error = std::strerror(errno);
    return nullptr;
  }
  if (S_ISDIR(st.st_mode)) {
    error = "is a directory";
    return nullptr;
  }
  if (!S_ISREG(st.st_mode)) {
    if (max_stream_bytes == 0 || S_ISBLK(st.st_mode) || S_ISSOCK(st.st_mode)) {
      error = "not a regular file";
      return nullptr;
    }
    return read_stream(fd, std::move(name), error, max_stream_bytes);
  }
  std::unique_ptr<SourceFile> f(new SourceFile());
  f->name_ = std::move(name);
  const auto len = static_cast<std::size_t>(st.st_size);
  if (len > 0) {
    void* p = mmap(nullptr, len, PROT_READ, MAP_PRIVATE, fd, 0);
    if (p == MAP_FAILED) {
      error = std::strerror(errno);
      return nullptr;
    }
    madvise(p, len, MADV_SEQUENTIAL);
    f->map_ = p;
    f->map_len_ = len;
    f->text_ = std::string_view(static_cast<const char*>(p), len);
  }
  return f;
}

// A pipe or a device is held in memory, so its size is bounded: /dev/zero
// given as a program must end with an error, not with memory exhausted.
std::unique_ptr<SourceFile> SourceFile::read_stream(int fd, std::string name, std::string& error,
                                                    std::uint64_t max_bytes) {
  const int flags = fcntl(fd, F_GETFL);
  if (flags >= 0) fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
  std::string text;
  std::array<char, 1 << 16> buf{};
  while (true) {
    const ssize_t n = ::read(fd, buf.data(), buf.size());
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      error = std::strerror(errno);
      return nullptr;
    }
    if (n == 0) break;
    if (text.size() + static_cast<std::size_t>(n) > max_bytes) {
      error = "larger than " + std::to_string(max_bytes >> 20) +
              " MiB read from a pipe or device; give usina the file itself (a file is mapped, "
              "not held in memory)";
      return nullptr;
    }
    text.append(buf.data(), static_cast<std::size_t>(n));
  }
  return from_string(std::move(name), std::move(text));
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

namespace {

// How many columns of a source line a diagnostic shows around its column.
constexpr std::size_t kShownColumns = 200;

// One byte sequence of a source line as shown: escaped when unprintable.
struct Shown {
  std::string text;
  std::size_t bytes = 1;
  std::size_t columns = 1;
};

// A tab stays a tab (the caret line uses one too, so it stays aligned).
Shown show_at(std::string_view line, std::size_t i) {
  if (line[i] == '\t') return {"\t", 1, 1};
  std::size_t n = utf8_sequence_at(line, i);
  const auto c = static_cast<unsigned char>(line[i]);
  if (n == 2 && c == 0xC2 && static_cast<unsigned char>(line[i + 1]) < 0xA0) n = 0;
  if (n == 0 || c < 0x20 || c == 0x7F) {
    std::string text = printable(line.substr(i, 1));
    const std::size_t width = text.size();
    return {std::move(text), 1, width};
  }
  return {std::string(line.substr(i, n)), n, 1};
}

// Where a long line's window starts: about half the window before `from`,
// never inside a UTF-8 sequence.
std::size_t window_start(std::string_view line, std::size_t from) {
  if (line.size() <= kShownColumns || from <= kShownColumns / 2) return 0;
  std::size_t start = std::min(from - kShownColumns / 2, line.size() - 1);
  while (start > 0 && (static_cast<unsigned char>(line[start]) & 0xC0) == 0x80)
    --start;
  return start;
}

// The line (a window of it when long), and a caret under bytes [from, to).
void show_line(std::string& out, std::string_view line, std::size_t from, std::size_t to,
               bool caret) {
  const std::size_t start = window_start(line, from);
  const std::size_t end = std::min(line.size(), start + kShownColumns);
  std::string text = start > 0 ? "..." : "";
  std::string under(text.size(), ' ');
  bool marked = false;
  for (std::size_t i = start; i < end;) {
    const Shown s = show_at(line, i);
    if (i < from) {
      under.append(s.columns, s.text == "\t" ? '\t' : ' ');
    } else if (i < to) {
      under.append(s.columns, marked ? '~' : '^');
      marked = true;
    }
    text += s.text;
    i += s.bytes;
  }
  if (end < line.size()) text += "...";
  if (!marked) under += '^';  // at the line's end (a missing word)
  out += "  " + text + "\n";
  if (caret) out += "  " + under + "\n";
}

}  // namespace

std::string render(const Diagnostic& d, const SourceManager& sources) {
  std::string out;
  const SourceFile* file = sources.get(d.loc.file);
  out += printable(file != nullptr ? file->name() : std::string("<input>"));
  if (d.loc.line > 0) {
    out += ':' + std::to_string(d.loc.line);
    if (d.loc.col > 0) out += ':' + std::to_string(d.loc.col);
  }
  out += ": ";
  out += severity_name(d.severity);
  out += ": ";
  out += printable(d.message);
  out += " [";
  out += code_name(d.code);
  out += "]\n";
  if (file == nullptr || d.loc.line == 0) return out;
  const std::string_view line = file->line_at(d.loc.line_offset);
  const std::size_t from = d.loc.col > 0 ? d.loc.col - 1 : 0;
  show_line(out, line, from, from + std::max<std::uint32_t>(d.loc.length, 1), d.loc.col > 0);
  return out;
}

}  // namespace usina::core
