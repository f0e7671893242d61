#include "dnc/web_static.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <array>
#include <iterator>
#include <optional>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <sys/stat.h>

namespace usina::dnc {
namespace {

namespace fs = std::filesystem;

// A page has few levels of folders; a deeper path is not one of its files.
constexpr std::size_t kMaxSegments = 16;

int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// One segment %-decoded; nothing for a bad escape, a NUL, a `/` or a `\`
// (a decoded `/` would rejoin what the split separated).
std::optional<std::string> decode_segment(std::string_view s) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    char c = s[i];
    if (c == '%') {
      if (i + 2 >= s.size()) return std::nullopt;
      const int hi = hex_value(s[i + 1]);
      const int lo = hex_value(s[i + 2]);
      if (hi < 0 || lo < 0) return std::nullopt;
      c = static_cast<char>(hi * 16 + lo);
      i += 2;
    }
    if (c == '\0' || c == '/' || c == '\\') return std::nullopt;
    out += c;
  }
  return out;
}

enum class Refusal { None, Malformed, Hidden };

// The path's segments ("/" is index.html); a refusal for a path that is no
// file name inside the root.
std::pair<Refusal, std::vector<std::string>> page_segments(std::string_view target) {
  std::string_view path = target.substr(0, target.find_first_of("?#"));
  if (path.empty() || path.front() != '/') return {Refusal::Malformed, {}};
  path.remove_prefix(1);
  std::vector<std::string> segments;
  while (!path.empty()) {
    const std::size_t slash = path.find('/');
    auto part = decode_segment(path.substr(0, slash));
    if (!part || part->empty() || *part == "." || *part == ".." || segments.size() >= kMaxSegments)
      return {Refusal::Malformed, {}};
    if (part->front() == '.') return {Refusal::Hidden, {}};
    segments.push_back(std::move(*part));
    if (slash == std::string_view::npos) break;
    path.remove_prefix(slash + 1);
    if (path.empty()) segments.emplace_back("index.html");  // a folder's page
  }
  if (segments.empty()) segments.emplace_back("index.html");
  return {Refusal::None, std::move(segments)};
}

// Whether `inner` (canonical) lies inside `root` (canonical), component by component.
bool inside(const fs::path& root, const fs::path& inner) {
  auto r = root.begin();
  auto i = inner.begin();
  for (; r != root.end(); ++r, ++i) {
    if (i == inner.end() || *r != *i) return false;
  }
  return i != inner.end();
}

HttpResponse plain(const HttpRequest& req, http::status status, std::string_view message) {
  HttpResponse res = error_response(req, status, message);
  res.set("X-Content-Type-Options", "nosniff");
  return res;
}

// The whole file read from an open descriptor; nothing when it cannot be.
std::optional<std::string> read_all(int fd, std::uint64_t size) {
  std::string body(static_cast<std::size_t>(size), '\0');
  std::size_t got = 0;
  while (got < body.size()) {
    const ssize_t n = ::read(fd, body.data() + got, body.size() - got);
    if (n <= 0) return std::nullopt;
    got += static_cast<std::size_t>(n);
  }
  return body;
}

}  // namespace

bool is_page_target(std::string_view target) {
  const std::string_view path = target.substr(0, target.find_first_of("?#"));
  return !(path == "/api" || path.substr(0, 5) == "/api/");
}

std::string_view content_type_of(std::string_view file_name) {
  static constexpr std::array<std::pair<std::string_view, std::string_view>, 13> kTypes{{
      {".html", "text/html; charset=utf-8"},
      {".js", "text/javascript; charset=utf-8"},
      {".mjs", "text/javascript; charset=utf-8"},
      {".css", "text/css; charset=utf-8"},
      {".json", "application/json"},
      {".map", "application/json"},
      {".svg", "image/svg+xml"},
      {".png", "image/png"},
      {".ico", "image/x-icon"},
      {".txt", "text/plain; charset=utf-8"},
      {".woff2", "font/woff2"},
      {".wasm", "application/wasm"},
      {".webmanifest", "application/manifest+json"},
  }};
  for (const auto& [ext, type] : kTypes) {
    if (file_name.size() > ext.size() && file_name.substr(file_name.size() - ext.size()) == ext)
      return type;
  }
  return "application/octet-stream";
}

fs::path default_web_root() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return {};
  const fs::path dir = exe.parent_path();
  for (const fs::path& candidate : {dir / "web", dir.parent_path() / "share" / "usina" / "web"}) {
    if (fs::is_directory(candidate, ec)) return candidate;
  }
  return {};
}

int open_beneath(const fs::path& root, const fs::path& relative) {
  if (relative.empty() || relative.is_absolute()) return -1;
  int dir = ::open(root.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
  for (auto it = relative.begin(); dir >= 0 && it != relative.end(); ++it) {
    const fs::path name = *it;
    const bool last = std::next(it) == relative.end();
    int fd = -1;
    if (name != "." && name != "..") {
      // Every folder of the path as a folder, never through a symlink.
      const int flags = O_RDONLY | O_NOFOLLOW | O_CLOEXEC | (last ? O_NONBLOCK : O_DIRECTORY);
      fd = ::openat(dir, name.c_str(), flags);
    }
    ::close(dir);
    if (last) return fd;
    dir = fd;
  }
  return -1;
}

WebFiles::WebFiles(WebFilesConfig config) : config_(std::move(config)) {
  std::error_code ec;
  if (!config_.root.empty() && fs::is_directory(config_.root, ec))
    root_ = fs::canonical(config_.root, ec);
  if (ec) root_.clear();
}

HttpResponse WebFiles::serve(const HttpRequest& req) const {
  if (req.method() != http::verb::get)
    return plain(req, http::status::method_not_allowed, "the page's files are only read (GET)");
  const std::string_view target(req.target().data(), req.target().size());
  const auto [refusal, segments] = page_segments(target);
  if (refusal == Refusal::Malformed) {
    return plain(req, http::status::bad_request,
                 "the path is malformed (no `.`, `..`, empty, `\\` or %-encoded `/` segments)");
  }
  if (refusal == Refusal::Hidden) return plain(req, http::status::not_found, "no such file");
  if (root_.empty()) {
    return plain(req, http::status::not_found,
                 "the web page is not installed: build web/ (scripts/build.sh) or set "
                 "[web] root in the configuration");
  }
  fs::path file = root_;
  for (const std::string& s : segments)
    file /= s;
  std::error_code ec;
  const fs::path real = fs::canonical(file, ec);
  // Through a symlink out of the root, or nothing there: the same 404.
  if (ec || !inside(root_, real)) return plain(req, http::status::not_found, "no such file");
  return file_response(req, real);
}

HttpResponse WebFiles::file_response(const HttpRequest& req, const fs::path& file) const {
  // The checks hold for the descriptor read, not for a name that may change:
  // the canonical path checked, opened beneath the root without following
  // a symlink at any level.
  const int fd = open_beneath(root_, file.lexically_relative(root_));
  if (fd < 0) return plain(req, http::status::not_found, "no such file");

  struct stat st {};

  std::optional<std::string> body;
  const bool regular = ::fstat(fd, &st) == 0 && S_ISREG(st.st_mode);
  const auto size = static_cast<std::uint64_t>(regular ? st.st_size : 0);
  if (regular && size <= config_.max_file_bytes) body = read_all(fd, size);
  ::close(fd);
  if (!regular) return plain(req, http::status::not_found, "no such file");
  if (size > config_.max_file_bytes) {
    return plain(req, http::status::internal_server_error,
                 fmt::format("the file is {} bytes, past the page's limit of {}", size,
                             config_.max_file_bytes));
  }
  if (!body) return plain(req, http::status::internal_server_error, "the file cannot be read");
  HttpResponse res{http::status::ok, req.version()};
  res.set(http::field::server, "usina");
  res.set(http::field::content_type, std::string(content_type_of(file.filename().string())));
  res.set("X-Content-Type-Options", "nosniff");
  res.set(http::field::cache_control, "no-cache");
  res.set("Content-Security-Policy",
          "default-src 'self'; connect-src 'self' ws: wss:; img-src 'self' data: blob:; "
          "object-src 'none'; base-uri 'none'; frame-ancestors 'none'");
  res.keep_alive(req.keep_alive());
  res.body() = std::move(*body);
  res.prepare_payload();
  return res;
}

}  // namespace usina::dnc
