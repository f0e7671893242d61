// store_import.hpp: the released set out to a folder.
#include <cerrno>
#include <cstring>

#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <sys/stat.h>

#include "core/output_file.hpp"
#include "dnc/store_audit.hpp"
#include "dnc/store_import.hpp"

namespace usina::dnc {
bool valid_extension(std::string_view e) {
  if (e.empty()) return true;
  if (e.size() < 2 || e.size() > 9 || e.front() != '.') return false;
  for (const char c : e.substr(1)) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
    if (!ok) return false;
  }
  return true;
}

namespace {

StoreResult<void> make_folder(const std::string& folder) {
  if (::mkdir(folder.c_str(), 0755) == 0 || errno == EEXIST) return {};
  return store_error(StoreErrorKind::Invalid,
                     fmt::format("cannot create {}: {}", folder, std::strerror(errno)));
}

}  // namespace

StoreResult<std::vector<ExportedFile>> released_set(Store& store, const std::string& extension) {
  auto programs = list_programs(store);
  if (!programs) return tl::unexpected(programs.error());
  std::vector<ExportedFile> out;
  for (const Program& p : *programs) {
    auto r = released_revision(store, p.name);
    if (!r) return tl::unexpected(r.error());
    if (*r) out.push_back({p.name, (*r)->hash, p.name + extension, (*r)->size});
  }
  return out;
}

StoreResult<void> audit_export(Store& store, const Actor& actor, std::size_t programs,
                               std::string_view to) {
  Transaction tx(store.db());
  if (auto b = tx.begin_write(); !b) return b;
  const nlohmann::json detail = {{"programs", programs}, {"to", to}};
  if (auto a = append_audit(store, actor, {"export.released", "", "", detail.dump()}); !a)
    return tl::unexpected(a.error());
  return tx.commit();
}

namespace {

StoreResult<void> write_one(Store& store, const std::string& folder, const ExportedFile& f) {
  auto bytes = revision_bytes(store, f.program, f.hash);
  if (!bytes) return tl::unexpected(bytes.error());
  if (auto w = core::write_file(folder + "/" + f.file, *bytes); !w)
    return store_error(StoreErrorKind::Backend, w.error());
  return {};
}

}  // namespace

StoreResult<std::vector<ExportedFile>> export_released(Store& store, const std::string& folder,
                                                       const std::string& extension,
                                                       const Actor& actor) {
  if (!valid_extension(extension)) {
    return store_error(
        StoreErrorKind::Invalid,
        fmt::format("extension '{}': a dot and 1 to 8 letters or digits", extension));
  }
  if (auto m = make_folder(folder); !m) return tl::unexpected(m.error());
  auto set = released_set(store, extension);
  if (!set) return set;
  std::string manifest;
  for (const ExportedFile& f : *set) {
    if (auto w = write_one(store, folder, f); !w) return tl::unexpected(w.error());
    manifest += fmt::format("{}  {}\n", f.hash, f.file);
  }
  if (auto w = core::write_file(folder + "/released.sha256", manifest); !w)
    return store_error(StoreErrorKind::Backend, w.error());
  if (auto a = audit_export(store, actor, set->size(), folder); !a)
    return tl::unexpected(a.error());
  return set;
}

}  // namespace usina::dnc
