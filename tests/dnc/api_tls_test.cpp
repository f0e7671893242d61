// HTTPS and WSS (`usina serve --tls-cert FILE --tls-key FILE`): a real TLS
// client that trusts only the test's self-signed certificate logs in,
// uploads a program and hears its event; plain HTTP and TLS before 1.2 are
// refused on the TLS port; bad certificate and key files are errors before
// the server listens, and exit status 2 from the command.
#include <gtest/gtest.h>
#include <openssl/ssl.h>

#include "core/diagnostic.hpp"
#include "dnc/sha256.hpp"
#include "server_fixture.hpp"
#include "support/files.hpp"
#include "support/usina_process.hpp"
#include "tls_client.hpp"

namespace usina::dnc {
namespace {

namespace websocket = boost::beast::websocket;
namespace ssl = boost::asio::ssl;

struct TlsFiles {
  test::TempDir dir;
  std::string cert, key;

  TlsFiles() {
    EXPECT_TRUE(test::make_self_signed(dir, "server")) << "openssl req failed";
    cert = dir.path("server.crt");
    key = dir.path("server.key");
  }
};

ServerConfig tls_config(const TlsFiles& f) {
  ServerConfig c;
  c.tls_cert = f.cert;
  c.tls_key = f.key;
  return c;
}

TEST(ApiTls, LogInAndUploadOverHttps) {
  const TlsFiles f;
  test::RunningServer s;
  s.start(tls_config(f));
  EXPECT_EQ(s.server().scheme(), "https");
  test::TlsClient c(s.client().port(), f.cert);
  const std::string prog = c.log_in("prog", test::kPassword);
  ASSERT_FALSE(prog.empty());
  EXPECT_GE(c.version, TLS1_2_VERSION);
  const std::string text = "G0 X1\nM2\n";
  const auto up = c.post("/api/programs", {{"name", "O900"}, {"text", text}}, prog);
  ASSERT_EQ(up.status, 201) << up.body;
  EXPECT_EQ(up.json()["revision"], sha256_hex(text));
  const auto back = c.get("/api/programs/O900", prog);
  ASSERT_EQ(back.status, 200);
  EXPECT_EQ(back.json()["revisions"][0]["revision"], sha256_hex(text));
  EXPECT_EQ(c.get("/api/programs/O900").status, 401);  // the roles hold over TLS too
}

TEST(ApiTls, CurlTrustingTheCertificateLogsIn) {
  if (std::system("curl --version >/dev/null 2>&1") != 0) GTEST_SKIP() << "no curl binary";
  const TlsFiles f;
  test::RunningServer s;
  s.start(tls_config(f));
  const std::string url = "https://127.0.0.1:" + std::to_string(s.client().port()) + "/api/login";
  const test::TempDir io;
  const std::string err = io.path("err");
  const auto r = test::shell(
      "curl -sS --cacert " + test::quote(f.cert) + " -H 'Content-Type: application/json' -d " +
          test::quote(R"({"user":"oper","password":")" + test::kPassword + R"("})") + " " +
          test::quote(url) + " 2>" + test::quote(err),
      err);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out, nullptr, false);
  ASSERT_TRUE(j.is_object()) << r.out;
  EXPECT_EQ(j["role"], "operator");
  EXPECT_EQ(j["token"].get<std::string>().size(), 64u);
}

TEST(ApiTls, EventsComeOverWss) {
  const TlsFiles f;
  test::RunningServer s;
  s.start(tls_config(f));
  test::TlsClient c(s.client().port(), f.cert);
  const std::string boss = c.log_in("boss", test::kPassword);
  boost::asio::io_context io;
  ssl::context ctx = test::client_context(f.cert);
  websocket::stream<boost::beast::ssl_stream<boost::beast::tcp_stream>> ws(io, ctx);
  boost::beast::get_lowest_layer(ws).connect(boost::asio::ip::tcp::endpoint(
      boost::asio::ip::make_address("127.0.0.1"), s.client().port()));
  ws.next_layer().handshake(ssl::stream_base::client);
  ws.handshake("127.0.0.1", "/api/events?token=" + boss);
  c.post("/api/programs", {{"name", "O901"}, {"text", "G0 X2\nM2\n"}}, boss);
  boost::beast::flat_buffer b;
  ws.read(b);
  const auto event = nlohmann::json::parse(boost::beast::buffers_to_string(b.data()));
  EXPECT_EQ(event["type"], "revision.created");
  EXPECT_EQ(event["name"], "O901");
}

TEST(ApiTls, PlainHttpOnTheTlsPortGetsNoAnswer) {
  const TlsFiles f;
  test::RunningServer s;
  s.start(tls_config(f));
  boost::asio::io_context io;
  boost::asio::ip::tcp::socket sock(io);
  sock.connect(boost::asio::ip::tcp::endpoint(boost::asio::ip::make_address("127.0.0.1"),
                                              s.client().port()));
  const std::string req = "POST /api/login HTTP/1.1\r\nHost: x\r\nContent-Length: 2\r\n\r\n{}";
  boost::asio::write(sock, boost::asio::buffer(req));
  std::string got;
  boost::system::error_code ec;
  std::array<char, 4096> buf{};
  while (!ec) {
    const std::size_t n = sock.read_some(boost::asio::buffer(buf), ec);
    got.append(buf.data(), n);
  }
  // The connection is closed (a TLS alert at most): no HTTP, no token in the clear.
  EXPECT_EQ(got.find("HTTP/"), std::string::npos) << got;
  EXPECT_EQ(got.find("token"), std::string::npos);
}

TEST(ApiTls, AClientOfferingOnlyTls11IsRefused) {
  const TlsFiles f;
  test::RunningServer s;
  s.start(tls_config(f));
  boost::asio::io_context io;
  ssl::context ctx = test::client_context(f.cert);
  SSL_CTX_set_min_proto_version(ctx.native_handle(), TLS1_VERSION);
  SSL_CTX_set_max_proto_version(ctx.native_handle(), TLS1_1_VERSION);
  SSL_CTX_set_cipher_list(ctx.native_handle(), "DEFAULT:@SECLEVEL=0");  // the client could
  boost::beast::ssl_stream<boost::beast::tcp_stream> stream(io, ctx);
  boost::beast::get_lowest_layer(stream).connect(boost::asio::ip::tcp::endpoint(
      boost::asio::ip::make_address("127.0.0.1"), s.client().port()));
  boost::system::error_code ec;
  stream.handshake(ssl::stream_base::client, ec);
  EXPECT_TRUE(ec) << "a TLS 1.1 handshake went through";
}

// The server's start with these files: its error, and whether it listens.
std::string start_error(const std::string& cert, const std::string& key) {
  const test::TempDir data;
  boost::asio::io_context io;
  ServerConfig c;
  c.tls_cert = cert;
  c.tls_key = key;
  auto s = Server::open(io, data.path("store"), c, test::fast_store());
  EXPECT_TRUE(s);
  if (!s) return "no server";
  std::string error = (*s)->start("127.0.0.1:0");
  EXPECT_EQ((*s)->endpoint().port(), 0) << "listening although the TLS files are bad";
  return error;
}

TEST(ApiTls, BadCertificateOrKeyFilesAreErrorsBeforeListening) {
  const TlsFiles f;
  ASSERT_TRUE(test::make_self_signed(f.dir, "other"));
  const std::string garbage = f.dir.write("garbage.pem", "-----BEGIN CERTIFICATE-----\nxx\n");
  const std::string missing = f.dir.path("missing.pem");
  EXPECT_TRUE(test::contains(start_error(missing, f.key), "cannot read the TLS certificate"));
  EXPECT_TRUE(test::contains(start_error(f.cert, missing), "cannot read the TLS key"));
  EXPECT_TRUE(test::contains(start_error(garbage, f.key), "is not a PEM certificate"));
  EXPECT_TRUE(test::contains(start_error(f.cert, garbage), "is not a PEM private key"));
  EXPECT_TRUE(test::contains(start_error(f.cert, f.dir.path("other.key")),
                             "does not belong to the certificate"));
  EXPECT_TRUE(test::contains(start_error(f.key, f.key), "is not a PEM certificate"));
}

TEST(ServeTls, AKeyNotMatchingTheCertificateExitsWith2BeforeListening) {
  const TlsFiles f;
  ASSERT_TRUE(test::make_self_signed(f.dir, "other"));
  const auto r = test::usina("serve --data " + test::quote(f.dir.path("data")) +
                             " --listen 127.0.0.1:0 --tls-cert " + test::quote(f.cert) +
                             " --tls-key " + test::quote(f.dir.path("other.key")));
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(test::contains(r.err, "does not belong to the certificate")) << r.err;
  EXPECT_FALSE(test::contains(r.err, "listening")) << r.err;
}

TEST(ServeTls, ACertificateWithoutItsKeyIsAUsageError) {
  const TlsFiles f;
  const auto r = test::usina("serve --data " + test::quote(f.dir.path("data")) +
                             " --listen 127.0.0.1:0 --tls-cert " + test::quote(f.cert));
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(test::contains(r.err, "--tls-cert and --tls-key go together")) << r.err;
}

TEST(ServeTls, TheServerTableNamesBothFilesOrNeither) {
  core::DiagnosticList diags;
  const auto both =
      read_server_config("[server]\ntls_cert = \"a.crt\"\ntls_key = \"a.key\"\n", 0, diags);
  ASSERT_TRUE(both);
  EXPECT_EQ(both->tls_cert, "a.crt");
  EXPECT_EQ(both->tls_key, "a.key");
  EXPECT_FALSE(read_server_config("[server]\ntls_cert = \"a.crt\"\n", 0, diags));
  EXPECT_FALSE(read_server_config("[server]\ntls_key = 3\n", 0, diags));
}

}  // namespace
}  // namespace usina::dnc
