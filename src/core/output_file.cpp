#include "core/output_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <utility>

#include <sys/random.h>
#include <sys/stat.h>

namespace usina::core {
namespace {

constexpr int kMaxLinkHops = 40;                  // as the kernel's ELOOP
constexpr std::size_t kBufferBytes = 256 * 1024;  // few write calls for big programs

tl::unexpected<std::string> failure(const std::string& path, std::string_view why) {
  return tl::unexpected("cannot write " + path + ": " + std::string(why));
}

std::string folder_of(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

std::string base_of(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

// A link planted by another user could point at any file root may write, so
// only links of the user's own or root's are followed.
tl::expected<void, std::string> check_link_owner(const std::string& path, const struct stat& st) {
  if (st.st_uid == ::geteuid() || st.st_uid == 0) return {};
  return failure(path, "it is a symbolic link that belongs to another user (uid " +
                           std::to_string(st.st_uid) +
                           "); usina follows only links of yours or of root");
}

// The file the path names, symbolic links followed (each hop checked).
tl::expected<std::string, std::string> resolve_links(const std::string& path) {
  std::string p = path;
  for (int hop = 0; hop < kMaxLinkHops; ++hop) {
    struct stat st {};

    if (::lstat(p.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return p;
    if (auto owner = check_link_owner(path, st); !owner) return tl::unexpected(owner.error());
    std::array<char, 4096> buf{};
    const ssize_t n = ::readlink(p.c_str(), buf.data(), buf.size() - 1);
    if (n < 0) return failure(path, std::strerror(errno));
    std::string to(buf.data(), static_cast<std::size_t>(n));
    p = to.front() == '/' ? to : folder_of(p) + "/" + to;
  }
  return failure(path, "too many levels of symbolic links");
}

std::string octal_mode(mode_t mode) {
  std::array<char, 8> buf{};
  std::snprintf(buf.data(), buf.size(), "%04o", static_cast<unsigned>(mode & 07777));
  return buf.data();
}

bool in_my_groups(gid_t gid) {
  if (gid == ::getegid()) return true;
  std::array<gid_t, 256> groups{};
  const int n = ::getgroups(static_cast<int>(groups.size()), groups.data());
  for (int i = 0; i < n; ++i)
    if (groups[static_cast<std::size_t>(i)] == gid) return true;
  return false;
}

// Whether the user could write the file were they not root: root replacing
// another user's read-only file is almost always a mistake.
bool writable_by_user(const struct stat& st) {
  if (st.st_uid == ::geteuid()) return (st.st_mode & S_IWUSR) != 0;
  if (in_my_groups(st.st_gid)) return (st.st_mode & S_IWGRP) != 0;
  return (st.st_mode & S_IWOTH) != 0;
}

mode_t new_file_mode() {
  // umask can only be read by setting it; a CLI runs one thread here.
  const mode_t mask = ::umask(0);
  ::umask(mask);
  return 0666 & ~mask;
}

std::string random_suffix() {
  std::array<unsigned char, 6> bytes{};
  if (::getrandom(bytes.data(), bytes.size(), 0) != static_cast<ssize_t>(bytes.size())) {
    const auto seed = static_cast<unsigned long>(::getpid()) ^
                      static_cast<unsigned long>(reinterpret_cast<std::uintptr_t>(&bytes));
    for (std::size_t i = 0; i < bytes.size(); ++i)
      bytes[i] = static_cast<unsigned char>(seed >> (8 * i));
  }
  static constexpr char kHex[] = "0123456789abcdef";
  std::string s;
  for (const unsigned char b : bytes) {
    s += kHex[b >> 4];
    s += kHex[b & 15];
  }
  return s;
}

// A new temporary beside `target`: O_EXCL and O_NOFOLLOW, so a name planted
// in the folder can never redirect the write.
tl::expected<int, std::string> create_partial(const std::string& path, const std::string& target,
                                              std::string& partial) {
  for (int attempt = 0; attempt < 16; ++attempt) {
    partial = folder_of(target) + "/." + base_of(target) + ".usina-" + random_suffix();
    const int fd =
        ::open(partial.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
    if (fd >= 0) return fd;
    if (errno != EEXIST) {
      const int err = errno;
      partial.clear();
      return failure(path,
                     std::string(std::strerror(err)) + " (in folder " + folder_of(target) + ")");
    }
  }
  partial.clear();
  return failure(path, "no free temporary name in its folder");
}

tl::expected<void, std::string> check_kind(const std::string& path, const struct stat& st) {
  if (S_ISDIR(st.st_mode)) return failure(path, "it is a folder");
  if (S_ISBLK(st.st_mode))
    return failure(path, "it is a block device (a disk); usina never writes one");
  if (S_ISSOCK(st.st_mode)) return failure(path, "it is a socket");
  return {};
}

tl::expected<void, std::string> check_inputs(const std::string& path,
                                             const std::vector<std::string>& inputs) {
  for (const std::string& input : inputs)
    if (auto ok = check_not_input(path, input); !ok) return ok;
  return {};
}

void sync_folder(const std::string& folder) {
  const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);  // best effort: some file systems refuse to sync a folder
  ::close(fd);
}

}  // namespace

// stdio forgets why a write failed; this remembers the first error.
struct OutputFile::Descriptor {
  int fd = -1;
  int error = 0;

  static ssize_t write(void* cookie, const char* data, std::size_t size) {
    auto* d = static_cast<Descriptor*>(cookie);
    std::size_t done = 0;
    while (done < size) {
      const ssize_t n = ::write(d->fd, data + done, size - done);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        if (d->error == 0) d->error = n < 0 ? errno : EIO;
        // Short, never -1: glibc's cookie files count a -1 as bytes done.
        return static_cast<ssize_t>(done);
      }
      done += static_cast<std::size_t>(n);
    }
    return static_cast<ssize_t>(done);
  }
};

tl::expected<void, std::string> check_not_input(const std::string& path, const std::string& input) {
  if (input.empty() || input == "-") return {};

  struct stat out {};

  struct stat in {};

  if (::stat(path.c_str(), &out) != 0 || ::stat(input.c_str(), &in) != 0) return {};
  if (out.st_dev != in.st_dev || out.st_ino != in.st_ino) return {};
  return failure(path, "it is also an input of this run (" + input +
                           "); usina never writes over what it reads: choose another name");
}

tl::expected<OutputFile, std::string> OutputFile::open(const std::string& path,
                                                       const std::vector<std::string>& inputs) {
  if (path.empty()) return failure("''", "no file name");

  struct stat first {};

  if (::lstat(path.c_str(), &first) == 0 && S_ISLNK(first.st_mode))
    if (auto owner = check_link_owner(path, first); !owner) return tl::unexpected(owner.error());
  if (auto ok = check_inputs(path, inputs); !ok) return tl::unexpected(ok.error());
  OutputFile f;
  f.path_ = path;

  struct stat st {};

  const bool exists = ::stat(path.c_str(), &st) == 0;
  if (exists) {
    if (auto ok = check_kind(path, st); !ok) return tl::unexpected(ok.error());
    if (!S_ISREG(st.st_mode)) {  // a device or a FIFO: in place, never replaced
      const int fd = ::open(path.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
      if (fd < 0) return failure(path, std::strerror(errno));
      if (auto ok = f.attach(fd); !ok) return tl::unexpected(ok.error());
      return f;
    }
    if (!writable_by_user(st))
      return failure(path, "it is read-only for you (owner uid " + std::to_string(st.st_uid) +
                               ", mode " + octal_mode(st.st_mode) +
                               "); remove it or make it writable first");
  }
  auto target = resolve_links(path);
  if (!target) return tl::unexpected(target.error());
  f.target_ = *target;
  f.mode_ = exists ? (st.st_mode & 07777) : new_file_mode();
  f.keep_owner_ = exists;
  f.uid_ = st.st_uid;
  f.gid_ = st.st_gid;
  auto fd = create_partial(path, f.target_, f.partial_);
  if (!fd) return tl::unexpected(fd.error());
  if (auto ok = f.attach(*fd); !ok) return tl::unexpected(ok.error());
  return f;
}

tl::expected<OutputFile, std::string> OutputFile::standard_output() {
  OutputFile f;
  f.path_ = "standard output";
  const int fd = ::dup(STDOUT_FILENO);
  if (fd < 0) return failure(f.path_, std::strerror(errno));
  if (auto ok = f.attach(fd); !ok) return tl::unexpected(ok.error());
  // A person watching a terminal sees each line as it is written.
  if (::isatty(fd) != 0) std::setvbuf(f.stream_, nullptr, _IOLBF, kBufferBytes);
  return f;
}

OutputFile::OutputFile(OutputFile&& other) noexcept
    : path_(std::move(other.path_)),
      target_(std::move(other.target_)),
      partial_(std::exchange(other.partial_, {})),
      stream_(std::exchange(other.stream_, nullptr)),
      descriptor_(std::move(other.descriptor_)),
      keep_owner_(other.keep_owner_),
      mode_(other.mode_),
      uid_(other.uid_),
      gid_(other.gid_) {}

OutputFile::~OutputFile() {
  discard();
}

tl::expected<void, std::string> OutputFile::attach(int fd) {
  descriptor_ = std::make_unique<Descriptor>(Descriptor{fd, 0});
  stream_ = ::fopencookie(descriptor_.get(), "w", {nullptr, &Descriptor::write, nullptr, nullptr});
  if (stream_ == nullptr) {
    ::close(fd);
    descriptor_.reset();
    discard();
    return failure(path_, "out of memory");
  }
  std::setvbuf(stream_, nullptr, _IOFBF, kBufferBytes);
  return {};
}

std::optional<std::string> OutputFile::write_error() {
  if (stream_ != nullptr) std::fflush(stream_);
  if (descriptor_ == nullptr || descriptor_->error == 0) return std::nullopt;
  return failure(path_, std::strerror(descriptor_->error)).value();
}

// Flushes and closes the stream (not the descriptor); the error says why a
// write failed, whenever it did.
tl::expected<void, std::string> OutputFile::close_stream() {
  const bool flushed = std::fflush(stream_) == 0 && std::ferror(stream_) == 0;
  std::fclose(stream_);
  stream_ = nullptr;
  if (flushed && descriptor_->error == 0) return {};
  return failure(path_, std::strerror(descriptor_->error != 0 ? descriptor_->error : EIO));
}

void OutputFile::discard() {
  if (stream_ != nullptr) std::fclose(stream_);
  stream_ = nullptr;
  if (descriptor_ != nullptr && descriptor_->fd >= 0) ::close(descriptor_->fd);
  descriptor_.reset();
  if (!partial_.empty()) ::unlink(partial_.c_str());
  partial_.clear();
}

tl::expected<void, std::string> OutputFile::commit() {
  if (stream_ == nullptr) return failure(path_, "already closed");
  if (auto closed = close_stream(); !closed) {
    discard();
    return closed;
  }
  const int fd = descriptor_->fd;
  if (partial_.empty()) {  // in place: a device or a FIFO
    descriptor_->fd = -1;
    if (::close(fd) != 0) return failure(path_, std::strerror(errno));
    return {};
  }
  // Root keeps the owner of a file it replaces; another user cannot, and the
  // new file is theirs (as any editor's save would make it).
  if (keep_owner_ && ::geteuid() == 0) (void)::fchown(fd, uid_, gid_);
  if (::fchmod(fd, mode_) != 0 || ::fsync(fd) != 0 ||
      ::close(std::exchange(descriptor_->fd, -1)) != 0 ||
      ::rename(partial_.c_str(), target_.c_str()) != 0) {
    const int e = errno;
    discard();
    return failure(path_, std::strerror(e));
  }
  partial_.clear();
  sync_folder(folder_of(target_));
  return {};
}

tl::expected<void, std::string> write_file(const std::string& path, std::string_view text,
                                           const std::vector<std::string>& inputs) {
  auto out = OutputFile::open(path, inputs);
  if (!out) return tl::unexpected(out.error());
  std::fwrite(text.data(), 1, text.size(), out->stream());
  return out->commit();
}

}  // namespace usina::core
