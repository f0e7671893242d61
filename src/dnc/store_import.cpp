#include "dnc/store_import.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <set>

#include <fmt/format.h>
#include <sys/stat.h>

#include "dnc/store_names.hpp"

namespace usina::dnc {
namespace {

namespace fs = std::filesystem;

// The file's bytes, refusing a link, a non-regular file or one past `max`.
tl::expected<std::string, std::string> read_file(const fs::path& path, std::uint64_t max) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0) {
    return tl::unexpected(errno == ELOOP ? std::string("a symbolic link; import the file itself")
                                         : std::string(std::strerror(errno)));
  }

  struct stat st {};

  std::string out;
  std::string error;
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    error = "not a regular file";
  } else if (static_cast<std::uint64_t>(st.st_size) > max) {
    error = fmt::format("{} bytes; the store takes at most {}", st.st_size, max);
  } else {
    out.resize(static_cast<std::size_t>(st.st_size));
    std::size_t got = 0;
    while (got < out.size()) {
      const ssize_t n = ::read(fd, out.data() + got, out.size() - got);
      if (n <= 0) break;
      got += static_cast<std::size_t>(n);
    }
    if (got != out.size()) error = "the file changed while it was read";
  }
  ::close(fd);
  if (!error.empty()) return tl::unexpected(error);
  return out;
}

std::vector<std::string> file_names(const fs::path& folder, std::error_code& ec) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.starts_with(".")) continue;
    std::error_code type_ec;
    if (entry.is_directory(type_ec) && !entry.is_symlink(type_ec)) continue;
    names.push_back(name);
  }
  std::sort(names.begin(), names.end());
  return names;
}

void import_one(Store& store, const fs::path& folder, ImportedFile& f, const ImportOptions& options,
                const Actor& actor) {
  f.program = fs::path(f.file).stem().string();
  if (auto ok = check_name("program name", f.program); !ok) {
    f.error = ok.error().message;
    return;
  }
  auto text = read_file(folder / f.file, store.options().max_program_bytes);
  if (!text) {
    f.error = text.error();
    return;
  }
  import_text(store, f, std::move(*text), options, actor);
}

}  // namespace

void import_text(Store& store, ImportedFile& f, std::string text, const ImportOptions& options,
                 const Actor& actor) {
  f.program = fs::path(f.file).stem().string();
  if (auto ok = check_name("program name", f.program); !ok) {
    f.error = ok.error().message;
    return;
  }
  const std::string reason =
      valid_utf8(f.file) ? fmt::format("{}: {}", options.reason, f.file) : options.reason;
  Upload u{f.program, options.machine_class, options.dialect, std::move(text),
           reason,    options.profile};
  auto put = put_revision(store, u, actor);
  if (!put) {
    f.error = put.error().message;
    return;
  }
  f.hash = put->revision.hash;
  f.created = put->created;
  f.state = std::string(state_name(put->revision.state));
}

void tally(ImportReport& report, ImportedFile f) {
  if (!f.error.empty()) {
    ++report.skipped;
  } else if (f.created) {
    ++report.imported;
  } else {
    ++report.unchanged;
  }
  report.files.push_back(std::move(f));
}

StoreResult<ImportReport> import_folder(Store& store, const std::string& folder,
                                        const ImportOptions& options, const Actor& actor) {
  std::error_code ec;
  const std::vector<std::string> names = file_names(folder, ec);
  if (ec) {
    return store_error(StoreErrorKind::Invalid,
                       fmt::format("cannot read the folder {}: {}", folder, ec.message()));
  }
  ImportReport report;
  std::set<std::string> seen;
  for (const std::string& name : names) {
    ImportedFile f;
    f.file = name;
    const std::string stem = fs::path(name).stem().string();
    if (!seen.insert(stem).second) {
      f.program = stem;
      f.error = fmt::format("another file of this folder is program {} already", stem);
    } else {
      import_one(store, folder, f, options, actor);
    }
    tally(report, std::move(f));
  }
  return report;
}

}  // namespace usina::dnc
