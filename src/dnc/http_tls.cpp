#include "dnc/http_tls.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>

#include <fmt/format.h>
#include <openssl/err.h>
#include <openssl/ssl.h>
#include <openssl/x509.h>

namespace usina::dnc {
namespace {

namespace ssl = boost::asio::ssl;

// Why `path` cannot be read, empty when it can (OpenSSL's own message for a
// missing file is "system lib", which tells a shop nothing).
std::string unreadable(const std::string& what, const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return fmt::format("cannot read the TLS {} {}: {}", what, path, std::strerror(errno));
  char c = 0;
  if (!in.get(c)) return fmt::format("the TLS {} {} is empty", what, path);
  return {};
}

// OpenSSL's reason for the last failure, its error queue emptied.
std::string openssl_reason(const boost::system::error_code& ec) {
  std::string reason = ec.message();
  ERR_clear_error();
  return reason;
}

std::string mismatch(const std::string& cert_file, const std::string& key_file) {
  ERR_clear_error();
  return fmt::format(
      "the TLS key {} does not belong to the certificate {}; give the key the certificate was "
      "made for",
      key_file, cert_file);
}

}  // namespace

tl::expected<std::shared_ptr<ssl::context>, std::string> make_tls_context(
    const std::string& cert_file, const std::string& key_file) {
  if (std::string why = unreadable("certificate", cert_file); !why.empty())
    return tl::unexpected(why);
  if (std::string why = unreadable("key", key_file); !why.empty()) return tl::unexpected(why);
  auto ctx = std::make_shared<ssl::context>(ssl::context::tls_server);
  // TLS 1.2 at the least; SSLv3, TLS 1.0 and 1.1 are refused at the handshake.
  SSL_CTX_set_min_proto_version(ctx->native_handle(), TLS1_2_VERSION);
  ctx->set_options(ssl::context::default_workarounds | ssl::context::no_sslv2 |
                   ssl::context::no_sslv3 | ssl::context::single_dh_use);
  // An encrypted key would make OpenSSL ask on the terminal: a server does
  // not ask, the key is refused instead.
  ctx->set_password_callback(
      [](std::size_t, ssl::context::password_purpose) { return std::string(); });
  boost::system::error_code ec;
  ctx->use_certificate_chain_file(cert_file, ec);
  if (ec) {
    return tl::unexpected(
        fmt::format("the TLS certificate {} is not a PEM certificate OpenSSL can use: {}",
                    cert_file, openssl_reason(ec)));
  }
  ctx->use_private_key_file(key_file, ssl::context::pem, ec);
  // OpenSSL checks the key against the certificate as it loads it.
  if (ec && ERR_GET_REASON(static_cast<unsigned long>(ec.value())) == X509_R_KEY_VALUES_MISMATCH)
    return tl::unexpected(mismatch(cert_file, key_file));
  if (ec) {
    return tl::unexpected(fmt::format("the TLS key {} is not a PEM private key OpenSSL can use: {}",
                                      key_file, openssl_reason(ec)));
  }
  if (SSL_CTX_check_private_key(ctx->native_handle()) != 1) {
    ERR_clear_error();
    return tl::unexpected(mismatch(cert_file, key_file));
  }
  return ctx;
}

}  // namespace usina::dnc
