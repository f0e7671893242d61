#include "dnc/server.hpp"

#include <charconv>

#include <fmt/format.h>

#include "dnc/http_tls.hpp"
#include "dnc/machine_settings.hpp"
#include "dnc/store_jobs.hpp"
#include "dnc/store_machines.hpp"
#include "dnc/store_utilisation.hpp"

namespace usina::dnc {

std::optional<boost::asio::ip::tcp::endpoint> parse_listen(std::string_view text) {
  const std::size_t colon = text.rfind(':');
  if (colon == std::string_view::npos || colon == 0) return std::nullopt;
  std::string_view host = text.substr(0, colon);
  const std::string_view port_text = text.substr(colon + 1);
  if (host.size() > 2 && host.front() == '[' && host.back() == ']')
    host = host.substr(1, host.size() - 2);
  unsigned port = 0;
  const auto [end, ec] =
      std::from_chars(port_text.data(), port_text.data() + port_text.size(), port);
  if (ec != std::errc() || end != port_text.data() + port_text.size() || port > 65535)
    return std::nullopt;
  boost::system::error_code bad;
  const auto address = boost::asio::ip::make_address(std::string(host), bad);
  if (bad) return std::nullopt;
  return boost::asio::ip::tcp::endpoint(address, static_cast<unsigned short>(port));
}

namespace {

// The machines an admin added through the API and has not retired, after
// the file's. A name in both, or settings this usina no longer reads, stop
// the start with the reason: which one to run is the admin's choice.
tl::expected<void, std::string> add_stored_machines(Store& store, ServerConfig& config) {
  auto stored = stored_machines(store);
  if (!stored) return tl::unexpected(stored.error().message);
  for (const StoredMachine& s : *stored) {
    if (s.retired_at_us != 0) continue;
    for (const ServerMachine& m : config.machines) {
      if (m.link.name == s.name)
        return tl::unexpected(fmt::format(
            "machine {} is in the configuration file and was added through the API too; "
            "remove or rename the file's",
            s.name));
    }
    auto m = machine_from_settings(nlohmann::json::parse(s.settings, nullptr, false));
    if (!m)
      return tl::unexpected(
          fmt::format("machine {} of the store cannot be read: {}", s.name, m.error()));
    m->from_store = true;
    if (!m->calendar) m->calendar = config.calendar;
    config.machines.push_back(std::move(*m));
  }
  return {};
}

}  // namespace

tl::expected<std::unique_ptr<Server>, std::string> Server::open(asio::io_context& io,
                                                                const std::string& where,
                                                                ServerConfig config,
                                                                StoreOptions options) {
  options.session_seconds = static_cast<std::int64_t>(config.session_hours * 3600.0);
  auto store = Store::open(where, std::move(options));
  if (!store) return tl::unexpected(store.error().message);
  // A job a previous run did not see to its end was cut off: never resent.
  // It ended, and its machines went off, when that run was last alive.
  auto alive = last_heartbeat(**store);
  if (!alive) return tl::unexpected(alive.error().message);
  auto cut = interrupt_unfinished_jobs(**store,
                                       "the server stopped while the job was queued or "
                                       "running (the bytes are those last recorded)",
                                       *alive);
  if (!cut) return tl::unexpected(cut.error().message);
  if (auto off = close_activity_of_dead_server(**store); !off)
    return tl::unexpected(off.error().message);
  if (auto added = add_stored_machines(**store, config); !added)
    return tl::unexpected(added.error());
  return std::unique_ptr<Server>(new Server(io, std::move(*store), std::move(config)));
}

Server::Server(asio::io_context& io, std::unique_ptr<Store> store, ServerConfig config)
    : io_(io), store_(std::move(store)), config_(std::move(config)) {
  machines_ = std::make_unique<Machines>(io_, *store_, events_, config_.machines);
  machines_->use_profiles(&config_.profiles);
  machines_->use_calendar(config_.calendar);
  toolpaths_ = std::make_unique<ToolpathService>(io_);
  api_ = std::make_unique<Api>(
      ApiContext{*store_, *machines_, events_, config_.profiles, toolpaths_.get(), &sheet_links_});
  web_ = std::make_unique<WebFiles>(WebFilesConfig{
      config_.web_root.empty() ? default_web_root() : std::filesystem::path(config_.web_root),
      config_.web_max_file_bytes});
  HttpHandlers handlers;
  handlers.later = [this](const HttpRequest& req, const std::string& origin, HttpAnswer& answer) {
    return api_->handle_later(req, origin, answer);
  };
  handlers.request = [this](const HttpRequest& req, const std::string& origin) {
    const std::string_view target(req.target().data(), req.target().size());
    // Only GET reads the page; any other method keeps the API's answer
    // (404 for a path that is no route).
    if (req.method() == http::verb::get && is_page_target(target)) return web_->serve(req);
    return api_->handle(req, origin);
  };
  handlers.take_stream = [this] { return api_->take_stream(); };
  handlers.upgrade = [this](HttpStream& stream, const HttpRequest& req) {
    return api_->upgrade(stream, req);
  };
  HttpLimits limits;
  limits.body_bytes = config_.max_upload;
  listener_ = std::make_shared<HttpListener>(io_, std::move(handlers), limits);
  add_data_outputs();
}

std::string Server::start(const std::string& listen) {
  const auto at = parse_listen(listen);
  if (!at)
    return fmt::format("cannot read the address `{}`; give host:port, as 127.0.0.1:8080", listen);
  if (!config_.tls_cert.empty() || !config_.tls_key.empty()) {
    auto tls = make_tls_context(config_.tls_cert, config_.tls_key);
    if (!tls) return tls.error();
    listener_->use_tls(std::move(*tls));
  }
  if (std::string error = listener_->listen(*at); !error.empty())
    return fmt::format("cannot listen on {}: {}", listen, error);
  if (std::string error = start_data_outputs(); !error.empty()) return error;
  listener_->start();
  machines_->start();
  return {};
}

void Server::stop(const std::string& reason, std::function<void()> stopped) {
  listener_->stop();
  machines_->stop(reason, [this, stopped = std::move(stopped)] {
    events_.close_all();
    if (shdr_) shdr_->stop();
    if (mqtt_) mqtt_->stop();
    if (stopped) stopped();
  });
}

}  // namespace usina::dnc
