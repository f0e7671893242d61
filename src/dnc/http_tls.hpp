// TLS for the HTTP API and its WebSocket (`usina serve --tls-cert FILE
// --tls-key FILE`, or `[server] tls_cert`/`tls_key`): an OpenSSL server
// context made from a PEM certificate chain and its private key, TLS 1.2 at
// the least. Every problem is found here, before the server listens: a file
// that cannot be read, a certificate or key OpenSSL cannot parse, a key that
// is not the certificate's.
#pragma once

#include <memory>
#include <string>

#include <boost/asio/ssl/context.hpp>
#include <tl/expected.hpp>

namespace usina::dnc {

tl::expected<std::shared_ptr<boost::asio::ssl::context>, std::string> make_tls_context(
    const std::string& cert_file, const std::string& key_file);

}  // namespace usina::dnc
