// Import and export over HTTP (docs/dnc.md, "Import and export"):
//   POST /api/import   a JSON list of files, each a revision, as the folder
//                      import makes them (store_import.hpp: one code);
//   GET  /api/export   the released set as a ustar archive, each file
//                      verified against its hash, with released.sha256.
// JSON in, because every other request is JSON and a name in it is only a
// name (a tar's entries carry paths, links and devices to refuse); a tar
// out, because its bytes are the programs' own (JSON strings cannot carry
// bytes that are not UTF-8) and `tar x && sha256sum -c released.sha256`
// checks the copy.
#include <filesystem>
#include <memory>
#include <set>

#include <fmt/format.h>

#include "dnc/api_json.hpp"
#include "dnc/api_router.hpp"
#include "dnc/base64.hpp"
#include "dnc/export_stream.hpp"
#include "dnc/store_import.hpp"
#include "dnc/store_names.hpp"

namespace usina::dnc {
namespace {

constexpr std::size_t kMaxImportFiles = 1000;

HttpResponse bad(const ApiCall& c, const std::string& message) {
  return error_response(c.req, http::status::bad_request, message);
}

// One entry's bytes: `text` (UTF-8) or `text_base64` (any bytes).
tl::expected<std::string, std::string> entry_bytes(const nlohmann::json& e) {
  auto text = string_field(e, "text", false);
  if (!text) return tl::unexpected(text.error());
  auto encoded = string_field(e, "text_base64", false);
  if (!encoded) return tl::unexpected(encoded.error());
  if (text->has_value() == encoded->has_value())
    return tl::unexpected(std::string("give each file \"text\" or \"text_base64\", one of them"));
  if (text->has_value()) return std::move(**text);
  auto bytes = from_base64(**encoded);
  if (!bytes) return tl::unexpected(std::string("\"text_base64\" is not base64"));
  return std::move(*bytes);
}

// The import's defaults, and each entry's own machine_class / dialect.
tl::expected<ImportOptions, std::string> options_of(const nlohmann::json& body,
                                                    const ImportOptions& base) {
  ImportOptions o = base;
  for (const auto& [key, into] :
       {std::pair{"machine_class", &o.machine_class}, std::pair{"dialect", &o.dialect}}) {
    auto v = string_field(body, key, false);
    if (!v) return tl::unexpected(v.error());
    if (v->has_value()) *into = **v;
  }
  return o;
}

const sim::MachineProfile* profile_of(const ApiCall& c, const std::string& machine_class) {
  const auto it = c.ctx.profiles.find(machine_class);
  return it == c.ctx.profiles.end() ? nullptr : &it->second;
}

// A file's name must be a name (a program name with an extension), never a path.
ImportedFile entry_file(const nlohmann::json& e) {
  ImportedFile f;
  auto name = string_field(e, "name", true);
  if (!name) {
    f.error = name.error();
    return f;
  }
  f.file = **name;
  if (auto ok = check_name("file name", f.file); !ok) f.error = ok.error().message;
  return f;
}

nlohmann::json report_json(const ImportReport& r) {
  nlohmann::json files = nlohmann::json::array();
  for (const ImportedFile& f : r.files) {
    files.push_back({{"name", f.file},
                     {"program", f.program},
                     {"revision", f.hash},
                     {"created", f.created},
                     {"state", f.state},
                     {"error", f.error}});
  }
  return {{"imported", r.imported},
          {"unchanged", r.unchanged},
          {"skipped", r.skipped},
          {"files", std::move(files)}};
}

// Checks the list before any of it is stored: a malformed request stores nothing.
std::optional<std::string> list_problem(const nlohmann::json& body) {
  const auto it = body.find("files");
  if (it == body.end() || !it->is_array())
    return "the field \"files\" must be a list of {\"name\", \"text\"} objects";
  if (it->empty()) return "the list \"files\" is empty";
  if (it->size() > kMaxImportFiles)
    return fmt::format("{} files; at most {} in one import", it->size(), kMaxImportFiles);
  for (const nlohmann::json& e : *it) {
    if (!e.is_object()) return "each entry of \"files\" must be an object";
  }
  return std::nullopt;
}

}  // namespace

HttpResponse api_import(ApiCall& c) {
  auto body = json_body(c.req);
  if (!body) return bad(c, body.error());
  if (auto problem = list_problem(*body)) return bad(c, *problem);
  ImportOptions base;
  base.machine_class.clear();  // as an upload: a program keeps its class
  auto reason = string_field(*body, "reason", false);
  if (!reason) return bad(c, reason.error());
  base.reason = reason->value_or("imported over HTTP");
  auto defaults = options_of(*body, base);
  if (!defaults) return bad(c, defaults.error());
  ImportReport report;
  std::set<std::string> seen;
  for (const nlohmann::json& e : (*body)["files"]) {
    ImportedFile f = entry_file(e);
    auto options = options_of(e, *defaults);
    auto bytes = entry_bytes(e);
    if (f.error.empty() && !options) f.error = options.error();
    if (f.error.empty() && !bytes) f.error = bytes.error();
    const std::string stem = std::filesystem::path(f.file).stem().string();
    if (f.error.empty() && !seen.insert(stem).second)
      f.error = fmt::format("another file of this import is program {} already", stem);
    if (f.error.empty()) {
      options->profile = profile_of(c, options->machine_class);
      import_text(c.ctx.store, f, std::move(*bytes), *options, c.actor());
    }
    tally(report, std::move(f));
  }
  return json_response(c.req, http::status::ok, report_json(report));
}

HttpResponse api_export(ApiCall& c) {
  if (const auto it = c.target.query.find("state");
      it != c.target.query.end() && it->second != "released") {
    return bad(c, fmt::format("state={}: only the released set is exported", it->second));
  }
  std::string extension = ".nc";
  if (const auto it = c.target.query.find("extension"); it != c.target.query.end())
    extension = it->second.empty() ? "" : "." + it->second;
  if (!valid_extension(extension))
    return bad(c, "extension: 1 to 8 letters or digits (without the dot)");
  auto set = released_set(c.ctx.store, extension);
  if (!set) return error_response(c.req, status_of(set.error()), set.error().message);
  const std::size_t programs = set->size();
  auto tar =
      std::make_shared<ReleasedTar>(c.ctx.store, std::move(*set), c.ctx.store.now_us() / 1'000'000);
  // The entry records the export as it starts: a client that stops reading
  // half-way has still been handed the set.
  if (auto a = audit_export(c.ctx.store, c.actor(), programs, "http"); !a)
    return error_response(c.req, status_of(a.error()), a.error().message);
  HttpResponse res{http::status::ok, c.req.version()};
  res.set(http::field::content_type, "application/x-tar");
  res.set(http::field::content_disposition, "attachment; filename=\"released.tar\"");
  res.keep_alive(c.req.keep_alive());
  StreamedBody body{[tar] { return tar->next(); }};
  if (c.stream != nullptr) {
    res.content_length(tar->size());
    *c.stream = std::move(body);
    return res;
  }
  // A caller that cannot stream (a test calling Api::handle) gets it whole.
  while (auto piece = body.next()) {
    if (piece->empty()) break;
    res.body() += *piece;
  }
  if (!tar->error().empty())
    return error_response(c.req, http::status::internal_server_error, tar->error());
  res.prepare_payload();
  return res;
}

}  // namespace usina::dnc
