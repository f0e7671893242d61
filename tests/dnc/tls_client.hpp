// A real HTTPS client for the TLS tests (Beast on OpenSSL, synchronous, one
// connection a request) that trusts only the test's own certificate and
// checks the server's name, as `curl --cacert` does; and the self-signed
// certificates the tests make with Debian's `openssl` binary.
#pragma once

#include <cstdlib>
#include <string>

#include <boost/asio/ssl.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/ssl.hpp>
#include <nlohmann/json.hpp>
#include <openssl/ssl.h>

#include "api_client.hpp"
#include "support/usina_process.hpp"

namespace usina::test {

namespace ssl = boost::asio::ssl;

// A self-signed certificate for 127.0.0.1 (and its key) made in `dir` as
// NAME.crt and NAME.key; false when openssl failed.
inline bool make_self_signed(const TempDir& dir, const std::string& name) {
  const std::string cmd =
      "openssl req -x509 -newkey ec -pkeyopt ec_paramgen_curve:prime256v1 -nodes -days 2 "
      "-subj /CN=127.0.0.1 -addext subjectAltName=IP:127.0.0.1 -keyout " +
      quote(dir.path(name + ".key")) + " -out " + quote(dir.path(name + ".crt")) +
      " >/dev/null 2>&1";
  return std::system(cmd.c_str()) == 0;
}

// A client context trusting `ca_file` only, checking the name 127.0.0.1.
inline ssl::context client_context(const std::string& ca_file) {
  ssl::context ctx(ssl::context::tls_client);
  ctx.load_verify_file(ca_file);
  ctx.set_verify_mode(ssl::verify_peer);
  ctx.set_verify_callback(ssl::host_name_verification("127.0.0.1"));
  return ctx;
}

class TlsClient : public ApiVerbs<TlsClient> {
 public:
  TlsClient(unsigned short port, std::string ca_file) : port_(port), ca_(std::move(ca_file)) {}

  Reply call(bhttp::verb method, const std::string& target, const std::string& body = "",
             const std::string& token = "") const {
    boost::asio::io_context io;
    ssl::context ctx = client_context(ca_);
    beast::ssl_stream<beast::tcp_stream> stream(io, ctx);
    beast::get_lowest_layer(stream).connect(
        boost::asio::ip::tcp::endpoint(boost::asio::ip::make_address("127.0.0.1"), port_));
    stream.handshake(ssl::stream_base::client);
    version = SSL_version(stream.native_handle());
    return round_trip(stream, api_request(method, target, body, token));
  }

  mutable int version = 0;  // the last connection's TLS version (SSL_version)

 private:
  unsigned short port_;
  std::string ca_;
};

}  // namespace usina::test
