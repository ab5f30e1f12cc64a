// facetc's remote cache against a real server: Debian's nginx, whose WebDAV
// module (PUT into a folder) is all a bazel-remote-layout cache needs. One
// build's entries serve the next machine, and a server killed mid-build costs
// compiles, never a wrong package. docs/reliability.md describes the tests.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>

#include <regex>

#include "facet/cache.h"
#include "facetc_test_util.h"
#include "process_util.h"

namespace facet::tools::testing {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

// Where Debian installs nginx, else the first one on $PATH; "" when none.
std::string find_nginx() {
  std::vector<fs::path> candidates = {"/usr/sbin/nginx"};
  if (const char* path = std::getenv("PATH")) {
    std::stringstream folders(path);
    for (std::string folder; std::getline(folders, folder, ':');) candidates.push_back(fs::path(folder) / "nginx");
  }
  for (const fs::path& c : candidates) {
    if (::access(c.c_str(), X_OK) == 0) return c.string();
  }
  return "";
}

// A port nothing listens on now (the kernel's pick for port 0).
int free_loopback_port() {
  int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ::bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr);
  socklen_t len = sizeof addr;
  ::getsockname(fd, reinterpret_cast<sockaddr*>(&addr), &len);
  ::close(fd);
  return ntohs(addr.sin_port);
}

bool accepts_connections(int port) {
  int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  addr.sin_port = htons(port);
  bool ok = ::connect(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) == 0;
  ::close(fd);
  return ok;
}

// One nginx with everything under `prefix`: config, pid file, logs, request
// body temporaries and the cache's root folder (root/ac, root/cas).
struct Nginx {
  std::string binary;
  fs::path prefix;
  int port = 0;
  pid_t pid = -1;  // the master; it leads the process group of its workers
};

std::string nginx_config(const Nginx& server) {
  const std::string p = server.prefix.string();
  std::string config;
  // As root, nginx would run its workers as nobody, who cannot write the
  // test's folders; as anyone else the directive is refused with a warning.
  if (::geteuid() == 0) config += "user root;\n";
  config += "daemon off;\nworker_processes 1;\npid " + p + "/nginx.pid;\nerror_log " + p + "/logs/error.log;\n";
  config += "events { worker_connections 256; }\n";
  config += "http {\n  access_log " + p + "/logs/access.log;\n";
  // Every temporary folder in the prefix: the defaults, under /var/lib/nginx,
  // are not writable for a user and must not be shared with a system nginx.
  for (const char* kind : {"client_body", "proxy", "fastcgi", "uwsgi", "scgi"}) {
    config += std::string("  ") + kind + "_temp_path " + p + "/tmp/" + kind + ";\n";
  }
  config += "  server {\n    listen 127.0.0.1:" + std::to_string(server.port) + ";\n    root " + p + "/root;\n";
  config += "    client_max_body_size 64m;\n";
  config += "    location / { dav_methods PUT; create_full_put_path on; }\n  }\n}\n";
  return config;
}

// Starts nginx on `server.port` and waits until it accepts connections;
// false when it exited instead (its error log says why).
bool start(Nginx& server) {
  for (const char* sub : {"root", "logs", "tmp"}) fs::create_directories(server.prefix / sub);
  write_all(server.prefix / "nginx.conf", nginx_config(server));
  server.pid = spawn_in(server.prefix,
                        {server.binary, "-p", server.prefix.string() + "/", "-c", (server.prefix / "nginx.conf").string(),
                         "-e", (server.prefix / "logs" / "error.log").string()},
                        server.prefix / "logs" / "stderr.log", /*own_group=*/true)
                   .pid;
  for (int i = 0; i < 1000; ++i) {
    if (!still_running(server.pid)) {
      wait_for(server.pid);
      server.pid = -1;
      return false;
    }
    if (accepts_connections(server.port)) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return false;
}

// A few ports in turn: another process may take a free port before nginx does.
bool start_on_a_free_port(Nginx& server) {
  for (int attempt = 0; attempt < 5; ++attempt) {
    server.port = free_loopback_port();
    if (start(server)) return true;
  }
  return false;
}

// SIGKILL to the master and its workers at once, as a crash or the OOM
// killer would end them: no request is finished, no file cleaned up.
void kill_nginx(Nginx& server) {
  if (server.pid <= 0) return;
  ::kill(-server.pid, SIGKILL);
  wait_for(server.pid);
  server.pid = -1;
  // The workers are not our children; wait until none holds the port.
  for (int i = 0; i < 500 && accepts_connections(server.port); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
}

std::string url(const Nginx& server) { return "http://127.0.0.1:" + std::to_string(server.port); }

std::vector<fs::path> files_under(const fs::path& dir) {
  std::vector<fs::path> found;
  if (!fs::exists(dir)) return found;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    if (e.is_regular_file()) found.push_back(e.path());
  }
  return found;
}

struct CacheCounts {
  int local = -1, remote = -1, compiled = -1;
};

// The numbers of --stats' "cache: local hits L / remote hits R / compiled C".
CacheCounts cache_counts(const std::string& err) {
  std::smatch m;
  static const std::regex line(R"(local hits (\d+) / remote hits (\d+) / compiled (\d+))");
  if (!std::regex_search(err, m, line)) return {};
  return {std::stoi(m[1]), std::stoi(m[2]), std::stoi(m[3])};
}

// What a crash must never leave on the server: under cas/ a file whose
// SHA-256 is not its name, under ac/ a value that is not the digest of a blob.
std::vector<std::string> broken_server_files(const fs::path& root) {
  std::vector<std::string> broken;
  for (const fs::path& blob : files_under(root / "cas")) {
    if (cache::sha256_hex(read_all(blob)) != blob.filename().string()) broken.push_back(blob.string());
  }
  for (const fs::path& action : files_under(root / "ac")) {
    std::string digest = read_all(action);
    if (digest.size() != 64 || !fs::is_regular_file(root / "cas" / digest)) broken.push_back(action.string());
  }
  return broken;
}

constexpr const char* kInstallHint =
    "nginx is not installed: run scripts/install-deps.sh (it installs Debian's nginx, whose WebDAV module these "
    "remote-cache tests use as the server)";

class NginxCacheTest : public FacetcTest {
 protected:
  void SetUp() override {
    FacetcTest::SetUp();
    server_.binary = find_nginx();
    ASSERT_FALSE(server_.binary.empty()) << kInstallHint;
    server_.prefix = dir_ / "nginx";
    ASSERT_TRUE(start_on_a_free_port(server_)) << read_all(server_.prefix / "logs" / "error.log")
                                               << read_all(server_.prefix / "logs" / "stderr.log");
  }
  void TearDown() override {
    kill_nginx(server_);
    FacetcTest::TearDown();
  }

  std::string reference(const std::string& shader) {
    EXPECT_EQ(facetc({example(shader), "--no-cache", "-o", "reference.facetpkg"}).exit_code, 0);
    return read_all(dir_ / "reference.facetpkg");
  }

  int put_requests() const {
    std::string log = read_all(server_.prefix / "logs" / "access.log");
    int puts = 0;
    for (size_t at = log.find("\"PUT "); at != std::string::npos; at = log.find("\"PUT ", at + 1)) ++puts;
    return puts;
  }

  Nginx server_;
};

TEST_F(NginxCacheTest, FirstBuildStoresEntriesAndAnEmptyLocalCacheIsServedByTheServer) {
  std::string clean = reference("Keywords.shader");
  FacetcRun first = facetc({example("Keywords.shader"), "--remote-cache", url(server_), "--cache-dir", "a", "--stats",
                            "-o", "a.facetpkg"});
  ASSERT_EQ(first.exit_code, 0) << first.err;
  EXPECT_THAT(first.err, HasSubstr("remote hits 0 / compiled 50"));
  // 50 entries and 64 include manifests, each an action-cache value and a blob.
  EXPECT_EQ(files_under(server_.prefix / "root" / "ac").size(), 114u);
  EXPECT_GE(files_under(server_.prefix / "root" / "cas").size(), 100u);
  EXPECT_THAT(broken_server_files(server_.prefix / "root"), ::testing::IsEmpty());

  FacetcRun second = facetc({example("Keywords.shader"), "--remote-cache", url(server_), "--cache-dir", "b", "--stats",
                             "-o", "b.facetpkg"});
  ASSERT_EQ(second.exit_code, 0) << second.err;
  EXPECT_THAT(second.err, HasSubstr("local hits 0 / remote hits 50 / compiled 0"));
  EXPECT_TRUE(read_all(dir_ / "a.facetpkg") == clean);
  EXPECT_TRUE(read_all(dir_ / "b.facetpkg") == clean);
}

// nginx answers a miss with "404 Not Found" and an HTML page of 153 bytes. A
// miss is a miss whatever the page says: no warning, so -Werror builds pass.
TEST_F(NginxCacheTest, MissesOnAnEmptyServerAreNotReportedAsCorrupt) {
  std::string clean = reference("Unlit.shader");
  FacetcRun build = facetc({example("Unlit.shader"), "--remote-cache", url(server_), "--cache-dir", "a", "--stats",
                            "-Werror", "-o", "a.facetpkg"});
  EXPECT_EQ(build.exit_code, 0) << build.err;
  EXPECT_THAT(build.err, Not(HasSubstr("corrupt")));
  EXPECT_THAT(build.err, HasSubstr("local hits 0 / remote hits 0 / compiled 2"));
  EXPECT_TRUE(read_all(dir_ / "a.facetpkg") == clean);
}

TEST_F(NginxCacheTest, ServerKilledMidBuildCostsCompilesNotCorrectness) {
  std::string clean = reference("Keywords.shader");
  // One thread, so that the build outlasts the first stores by long enough.
  // The 64 include manifests are stored while preprocessing (128 PUTs, blob
  // and action-cache value each), the 50 entries while compiling: the kill
  // comes after 10 entries, with 40 still to compile and store.
  Spawned build = spawn_in(dir_,
                           {FACETC_PATH, example("Keywords.shader"), "-j1", "--remote-cache", url(server_),
                            "--cache-dir", "a", "--stats", "-o", "a.facetpkg"},
                           dir_ / "a.log");
  while (put_requests() < 128 + 20 && still_running(build.pid)) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  ASSERT_TRUE(still_running(build.pid)) << "the build ended before nginx was killed; " << put_requests() << " PUTs\n"
                                 << read_all(dir_ / "a.log");
  kill_nginx(server_);
  Ended ended = wait_for(build.pid);
  ASSERT_TRUE(ended.exited && ended.code == 0) << read_all(dir_ / "a.log");
  EXPECT_THAT(read_all(dir_ / "a.log"), HasSubstr("remote hits 0 / compiled 50"));
  EXPECT_TRUE(read_all(dir_ / "a.facetpkg") == clean) << "a build whose server died mid-build is still right";
  EXPECT_THAT(broken_server_files(server_.prefix / "root"), ::testing::IsEmpty());

  // Restarted on the same folder: what it stored before the kill is served,
  // the rest is compiled (and stored), and the package is the clean one.
  ASSERT_TRUE(start(server_) || start_on_a_free_port(server_)) << read_all(server_.prefix / "logs" / "error.log");
  FacetcRun next = facetc({example("Keywords.shader"), "--remote-cache", url(server_), "--cache-dir", "b", "--stats",
                           "-o", "b.facetpkg"});
  ASSERT_EQ(next.exit_code, 0) << next.err;
  CacheCounts counts = cache_counts(next.err);
  EXPECT_EQ(counts.local, 0) << next.err;
  EXPECT_GT(counts.remote, 0) << next.err;
  EXPECT_EQ(counts.remote + counts.compiled, 50) << next.err;
  EXPECT_TRUE(read_all(dir_ / "b.facetpkg") == clean);

  FacetcRun repaired = facetc({example("Keywords.shader"), "--remote-cache", url(server_), "--cache-dir", "c",
                               "--stats", "-o", "c.facetpkg"});
  ASSERT_EQ(repaired.exit_code, 0) << repaired.err;
  EXPECT_THAT(repaired.err, HasSubstr("local hits 0 / remote hits 50 / compiled 0"));
  EXPECT_TRUE(read_all(dir_ / "c.facetpkg") == clean);
}

}  // namespace
}  // namespace facet::tools::testing
