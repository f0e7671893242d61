// The web page's files, served by `usina serve` from a folder (docs/web.md):
// every request whose path is not under /api/. This is hostile-input code.
// A path is %-decoded once and split into segments. Any `.` or `..`
// segment, an empty segment, a `\`, a NUL or a %-encoded `/` is refused
// (400). A name starting with `.` is never served. The file found is
// resolved through its symlinks and must still lie inside the root (else
// 404). It must be a regular file of at most `max_file_bytes`.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "dnc/api_http.hpp"

namespace usina::dnc {

struct WebFilesConfig {
  std::filesystem::path root;                  // the built page (web/ built by esbuild)
  std::uint64_t max_file_bytes = 32ull << 20;  // a larger file is not served (500)
};

// True for a target the page answers: anything but /api and /api/...
bool is_page_target(std::string_view target);

// The Content-Type of a file name's extension; application/octet-stream
// for one not listed.
std::string_view content_type_of(std::string_view file_name);

// The folder the page is read from when the configuration names none:
// beside the binary (`web/`, as the build tree has it), else the install
// prefix's `share/usina/web`. Empty when neither exists.
std::filesystem::path default_web_root();

// The file at `relative` beneath the folder `root` (both as fs::canonical
// gives them: no symlink, `.` or `..`), opened for reading one component at
// a time with O_NOFOLLOW. A folder of the path swapped for a symlink after
// it was checked fails the open instead of being followed (O_NOFOLLOW on
// the whole path guards only its last component). The descriptor, or -1.
int open_beneath(const std::filesystem::path& root, const std::filesystem::path& relative);

class WebFiles {
 public:
  explicit WebFiles(WebFilesConfig config);

  // The answer to a GET of a page file (405 for any other method).
  HttpResponse serve(const HttpRequest& req) const;

  const std::filesystem::path& root() const { return root_; }

 private:
  HttpResponse file_response(const HttpRequest& req, const std::filesystem::path& file) const;

  std::filesystem::path root_;  // canonical; empty when the folder does not exist
  WebFilesConfig config_;
};

}  // namespace usina::dnc
