// The page's files (web_static.hpp): served with their content types, and
// every hostile path refused: `..` plain or %-encoded, absolute paths,
// symlinks out of the root, hidden files, files too large, what is not a
// regular file, any method but GET.
#include "dnc/web_static.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <sys/stat.h>

#include "dnc/server_config.hpp"
#include "server_fixture.hpp"

namespace usina::dnc {
namespace {

namespace fs = std::filesystem;

void write(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << text;
}

class WebFilesTest : public ::testing::Test {
 protected:
  void SetUp() override {
    base_ = fs::temp_directory_path() / ("usina_web_" + std::to_string(::getpid()));
    fs::remove_all(base_);
    root_ = base_ / "root";
    write(root_ / "index.html", "<!doctype html><title>usina</title>");
    write(root_ / "app.js", "console.log(1)");
    write(root_ / "style.css", "body{}");
    write(root_ / "img" / "logo.svg", "<svg/>");
    write(root_ / "data.bin", "xyz");
    write(root_ / ".htpasswd", "hidden");
    write(root_ / "big.js", std::string(4096, 'x'));
    write(base_ / "outside" / "secret.txt", "SECRET");
    fs::create_symlink(base_ / "outside" / "secret.txt", root_ / "secret.txt");
    fs::create_symlink(base_ / "outside", root_ / "out");
    fs::create_symlink(root_ / "app.js", root_ / "alias.js");
    ASSERT_EQ(::mkfifo((root_ / "pipe.js").c_str(), 0600), 0);
  }

  void TearDown() override { fs::remove_all(base_); }

  HttpResponse get(const std::string& target, http::verb method = http::verb::get) const {
    WebFiles files(WebFilesConfig{root_, 1024});
    HttpRequest req{method, target, 11};
    return files.serve(req);
  }

  static std::string type(const HttpResponse& r) {
    return std::string(r[http::field::content_type]);
  }

  fs::path base_;
  fs::path root_;
};

TEST_F(WebFilesTest, TheRootIsTheIndexPage) {
  const HttpResponse r = get("/");
  EXPECT_EQ(r.result(), http::status::ok);
  EXPECT_EQ(r.body(), "<!doctype html><title>usina</title>");
  EXPECT_EQ(type(r), "text/html; charset=utf-8");
  EXPECT_EQ(get("/?x=1#top").result(), http::status::ok);
}

TEST_F(WebFilesTest, EachFileHasTheContentTypeOfItsExtension) {
  EXPECT_EQ(type(get("/app.js")), "text/javascript; charset=utf-8");
  EXPECT_EQ(type(get("/style.css")), "text/css; charset=utf-8");
  EXPECT_EQ(type(get("/img/logo.svg")), "image/svg+xml");
  EXPECT_EQ(type(get("/data.bin")), "application/octet-stream");
  const HttpResponse r = get("/app.js");
  EXPECT_EQ(r["X-Content-Type-Options"], "nosniff");
  EXPECT_NE(std::string(r["Content-Security-Policy"]).find("default-src 'self'"),
            std::string::npos);
}

TEST_F(WebFilesTest, DotDotSegmentsAreRefused) {
  for (const char* t : {"/../outside/secret.txt", "/img/../index.html", "/img/..", "/./app.js"}) {
    const HttpResponse r = get(t);
    EXPECT_EQ(r.result(), http::status::bad_request) << t;
    EXPECT_EQ(r.body().find("SECRET"), std::string::npos) << t;
  }
}

TEST_F(WebFilesTest, EncodedDotDotIsRefused) {
  for (const char* t : {"/%2e%2e/outside/secret.txt", "/%2E%2E/outside/secret.txt",
                        "/img/%2e%2e/%2e%2e/outside/secret.txt", "/..%2foutside%2fsecret.txt",
                        "/img%2F..%2F..%2Foutside%2Fsecret.txt", "/%2e/app.js"}) {
    EXPECT_EQ(get(t).result(), http::status::bad_request) << t;
  }
}

TEST_F(WebFilesTest, AbsolutePathsAreRefused) {
  for (const char* t : {"//etc/passwd", "/%2Fetc%2Fpasswd", "etc/passwd",
                        "http://127.0.0.1/../../etc/passwd", "/img//logo.svg"}) {
    EXPECT_EQ(get(t).result(), http::status::bad_request) << t;
  }
}

TEST_F(WebFilesTest, BackslashesNulsAndBadEscapesAreRefused) {
  for (const char* t : {"/..%5c..%5coutside%5csecret.txt", "/img\\logo.svg", "/app.js%00.html",
                        "/app%2", "/app%zz.js"}) {
    EXPECT_EQ(get(t).result(), http::status::bad_request) << t;
  }
}

TEST_F(WebFilesTest, SymlinksOutOfTheRootAreNotFollowed) {
  for (const char* t : {"/secret.txt", "/out/secret.txt"}) {
    const HttpResponse r = get(t);
    EXPECT_EQ(r.result(), http::status::not_found) << t;
    EXPECT_EQ(r.body().find("SECRET"), std::string::npos) << t;
  }
  // A symlink that stays inside the root is one of the page's files.
  EXPECT_EQ(get("/alias.js").body(), "console.log(1)");
}

TEST_F(WebFilesTest, HiddenFilesAreNeverServed) {
  EXPECT_EQ(get("/.htpasswd").result(), http::status::not_found);
  EXPECT_EQ(get("/%2ehtpasswd").result(), http::status::not_found);
}

TEST_F(WebFilesTest, AFileLargerThanTheLimitIsNotServed) {
  const HttpResponse r = get("/big.js");
  EXPECT_EQ(r.result(), http::status::internal_server_error);
  EXPECT_NE(r.body().find("4096 bytes"), std::string::npos);
}

TEST_F(WebFilesTest, FoldersPipesAndMissingFilesAreNotFound) {
  EXPECT_EQ(get("/img").result(), http::status::not_found);
  EXPECT_EQ(get("/img/").result(), http::status::not_found);  // no index.html in it
  EXPECT_EQ(get("/pipe.js").result(), http::status::not_found);
  EXPECT_EQ(get("/nothing.js").result(), http::status::not_found);
}

TEST_F(WebFilesTest, OnlyGetIsAnswered) {
  EXPECT_EQ(get("/app.js", http::verb::post).result(), http::status::method_not_allowed);
  EXPECT_EQ(get("/app.js", http::verb::put).result(), http::status::method_not_allowed);
  EXPECT_EQ(get("/app.js", http::verb::delete_).result(), http::status::method_not_allowed);
}

TEST_F(WebFilesTest, APathDeeperThanAPageIsRefused) {
  std::string deep;
  for (int i = 0; i < 40; ++i)
    deep += "/a";
  EXPECT_EQ(get(deep).result(), http::status::bad_request);
}

TEST_F(WebFilesTest, AMissingRootSaysThePageIsNotInstalled) {
  WebFiles files(WebFilesConfig{base_ / "no-such-folder", 1024});
  const HttpResponse r = files.serve(HttpRequest{http::verb::get, "/", 11});
  EXPECT_EQ(r.result(), http::status::not_found);
  EXPECT_NE(r.body().find("not installed"), std::string::npos);
}

TEST(WebTargets, EverythingOutsideApiIsThePage) {
  EXPECT_FALSE(is_page_target("/api"));
  EXPECT_FALSE(is_page_target("/api/programs"));
  EXPECT_FALSE(is_page_target("/api?x=1"));
  EXPECT_TRUE(is_page_target("/"));
  EXPECT_TRUE(is_page_target("/apiary.js"));
  EXPECT_TRUE(is_page_target("/index.html"));
}

TEST(WebConfig, TheWebTableIsRead) {
  core::DiagnosticList diags;
  auto c = read_server_config("[web]\nroot = \"page\"\nmax_file_bytes = 2048\n", 0, diags);
  ASSERT_TRUE(c);
  EXPECT_EQ(c->web_root, "page");
  EXPECT_EQ(c->web_max_file_bytes, 2048u);
  EXPECT_FALSE(read_server_config("[web]\nroot = 3\n", 0, diags));
  EXPECT_FALSE(read_server_config("[web]\nmax_file_bytes = 10\n", 0, diags));
}

TEST_F(WebFilesTest, TheServerAnswersThePageBesideTheApi) {
  test::RunningServer server;
  ServerConfig config;
  config.web_root = root_.string();
  server.start(std::move(config));
  const test::ApiClient client = server.client();
  EXPECT_EQ(client.get("/").body, "<!doctype html><title>usina</title>");
  EXPECT_EQ(client.get("/%2e%2e/outside/secret.txt").status, 400);
  EXPECT_EQ(client.get("/out/secret.txt").status, 404);
  const test::Reply api = client.get("/api/no-such-route");
  EXPECT_EQ(api.status, 404);
  EXPECT_EQ(api.json().value("error", ""), "no such route");
  EXPECT_EQ(client.get("/api/programs").status, 401);
  // A method other than GET on a path outside /api/ is still no route.
  EXPECT_EQ(client.call(boost::beast::http::verb::post, "/index.html", "{}").status, 404);
}

}  // namespace
}  // namespace usina::dnc
