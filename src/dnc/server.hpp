// `usina serve`, the whole server on one event loop: the store, the
// machines' stations and job queues, the HTTP API and its event stream.
// Opening marks the jobs a previous run did not see to their end as
// interrupted; stopping interrupts the running jobs, writes their ends,
// closes the ports and the connections.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <tl/expected.hpp>

#include "dnc/api_events.hpp"
#include "dnc/api_router.hpp"
#include "dnc/http_listener.hpp"
#include "dnc/mqtt_publisher.hpp"
#include "dnc/mtconnect_adapter.hpp"
#include "dnc/server_config.hpp"
#include "dnc/server_machines.hpp"
#include "dnc/sheet_links.hpp"
#include "dnc/store.hpp"
#include "dnc/web_static.hpp"
#include "dnc/web_toolpath_service.hpp"

namespace usina::dnc {

class Server {
 public:
  // `where`: a folder (SQLite) or a postgresql:// URL.
  static tl::expected<std::unique_ptr<Server>, std::string> open(asio::io_context& io,
                                                                 const std::string& where,
                                                                 ServerConfig config,
                                                                 StoreOptions options = {});

  // Listens on `listen` ("127.0.0.1:8080", port 0 for any), over TLS when
  // the configuration names a certificate and key, and opens the machines'
  // ports; an error message when it cannot listen or the TLS files are bad
  // (found before listening).
  std::string start(const std::string& listen);
  // Interrupts the running jobs with `reason`; `stopped` runs when their
  // ends are written and the ports and connections are closed.
  void stop(const std::string& reason, std::function<void()> stopped);

  boost::asio::ip::tcp::endpoint endpoint() const { return listener_->local_endpoint(); }

  // "https" when the API is served over TLS, else "http".
  std::string scheme() const { return listener_->tls() != nullptr ? "https" : "http"; }

  Store& store() { return *store_; }

  Machines& machines() { return *machines_; }

  EventHub& events() { return events_; }

  ToolpathService& toolpaths() { return *toolpaths_; }

  // The MTConnect adapter's address ([mtconnect]); nothing when it is off.
  std::optional<boost::asio::ip::tcp::endpoint> mtconnect_endpoint() const;

 private:
  Server(asio::io_context& io, std::unique_ptr<Store> store, ServerConfig config);
  void add_data_outputs();
  std::string start_data_outputs();

  asio::io_context& io_;
  std::unique_ptr<Store> store_;
  ServerConfig config_;
  EventHub events_;
  SheetLinks sheet_links_;  // a key of this server's life
  std::unique_ptr<Machines> machines_;
  std::unique_ptr<Api> api_;
  std::unique_ptr<WebFiles> web_;  // the page: every path outside /api/
  std::shared_ptr<HttpListener> listener_;
  std::unique_ptr<ShdrAdapter> shdr_;
  std::unique_ptr<MqttPublisher> mqtt_;
  // Last: gone first, its pool's threads joined while the rest still stands.
  std::unique_ptr<ToolpathService> toolpaths_;
};

// "host:port" ("[::1]:8080" for IPv6); nothing when malformed.
std::optional<boost::asio::ip::tcp::endpoint> parse_listen(std::string_view text);

}  // namespace usina::dnc
