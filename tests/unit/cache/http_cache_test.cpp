// The bazel-remote HTTP backend against a local server started by the test.
#include <arpa/inet.h>
#include <fcntl.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <filesystem>

#include "facet/cache.h"
#include "unit/test_http_server.h"

namespace facet::cache {
namespace {

TEST(CacheHttpTest, StoresInTheBazelRemoteLayoutAndLoadsBack) {
  test_http::TestHttpServer server(sha256_hex);
  HttpCache remote(server.url() + "/");
  const std::string key = "0123456789abcdef0123456789abcdef", bytes = "entry bytes\0\x01\x02";
  StoredBytes miss = remote.load_bytes(key);
  EXPECT_FALSE(miss.bytes) << "a miss";
  EXPECT_EQ(miss.problem, "") << "a miss is not a problem";
  ASSERT_TRUE(remote.store_bytes(key, bytes));
  auto objects = server.objects();
  std::string digest = sha256_hex(bytes);
  EXPECT_EQ(objects.at("/cas/" + digest), bytes);
  EXPECT_EQ(objects.at("/ac/" + sha256_hex(key)), digest);
  auto back = remote.load_bytes(key).bytes;
  ASSERT_TRUE(back);
  EXPECT_EQ(*back, bytes);
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
}

TEST(CacheHttpTest, TamperedOrMissingBlobsAreMisses) {
  test_http::TestHttpServer server(sha256_hex);
  HttpCache remote(server.url());
  const std::string key = "fedcba9876543210fedcba9876543210";
  ASSERT_TRUE(remote.store_bytes(key, "good"));
  server.set("/cas/" + sha256_hex("good"), "evil");
  StoredBytes tampered = remote.load_bytes(key);
  EXPECT_FALSE(tampered.bytes) << "a blob must hash to its name";
  EXPECT_EQ(tampered.problem, "its blob does not hash to its name");
  server.set("/ac/" + sha256_hex(key), "not a digest");
  EXPECT_FALSE(remote.load_bytes(key).bytes);
  EXPECT_EQ(remote.load_bytes(key).problem, "the action-cache value is not a digest");
  server.set("/ac/" + sha256_hex(key), sha256_hex("gone"));
  EXPECT_FALSE(remote.load_bytes(key).bytes);
}

TEST(CacheHttpTest, ServerDownIsAMissNotAFailure) {
  std::string url;
  {
    test_http::TestHttpServer server(sha256_hex);
    url = server.url();
  }  // stopped: its port is closed
  HttpCache remote(url, 2000);
  EXPECT_FALSE(remote.load_bytes("0123456789abcdef0123456789abcdef").bytes);
  EXPECT_FALSE(remote.store_bytes("0123456789abcdef0123456789abcdef", "x"));
}

// A server that accepts connections and never answers: each request would
// wait out the timeout, one a program, and a build of many programs took
// minutes. After the first timeout the server is not asked again.
TEST(CacheHttpTest, AServerThatNeverAnswersCostsOneTimeoutNotOneARequest) {
  int listener = ::socket(AF_INET, SOCK_STREAM, 0);
  ASSERT_GE(listener, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ASSERT_EQ(::bind(listener, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
  ASSERT_EQ(::listen(listener, 64), 0);  // connections complete in the backlog, unanswered
  socklen_t length = sizeof address;
  ASSERT_EQ(::getsockname(listener, reinterpret_cast<sockaddr*>(&address), &length), 0);
  const std::string url = "http://127.0.0.1:" + std::to_string(ntohs(address.sin_port));
  RemoteServers servers;  // a Compiler's, shared by its builds
  HttpCache remote(url, 500, servers.down_flag(url));
  EXPECT_FALSE(remote.down());
  EXPECT_FALSE(remote.load_bytes("0123456789abcdef0123456789abcdef").bytes);
  EXPECT_TRUE(remote.down());
  HttpCache next_build(url, 500, servers.down_flag(url));
  EXPECT_TRUE(next_build.down());
  for (int i = 0; i < 20; ++i) {
    EXPECT_FALSE(next_build.load_bytes("0123456789abcdef0123456789abcdef").bytes);
    EXPECT_FALSE(next_build.store_bytes("0123456789abcdef0123456789abcdef", "x"));
  }
  EXPECT_FALSE(HttpCache(url, 500, servers.down_flag(url + "/other")).down()) << "another server's flag";
  // Every request would have left a connection in the backlog: one did.
  ASSERT_EQ(::fcntl(listener, F_SETFL, O_NONBLOCK), 0);
  int connections = 0;
  for (int c; (c = ::accept(listener, nullptr, nullptr)) >= 0; ++connections) ::close(c);
  EXPECT_EQ(connections, 1);
  ::close(listener);
}

// The server's /ac/ entry of one key names the blob of another: the entry
// decodes, but is bound to the other key, so it is refused and not copied
// into the local folder.
TEST(CacheHttpTest, AnEntryServedForAnotherKeyIsRefused) {
  test_http::TestHttpServer server(sha256_hex);
  const std::string key = "0123456789abcdef0123456789abcdef", other = "fedcba9876543210fedcba9876543210";
  CacheEntry entry{{.spirv = {0x07230203, 1, 2, 3}}, /*token_hash=*/5};
  CacheStores stores{.remote = HttpCache(server.url())};
  stores.store_entry(other, entry);
  server.set("/ac/" + sha256_hex(key), server.objects().at("/ac/" + sha256_hex(other)));
  auto dir = std::filesystem::temp_directory_path() / ("facet_http_cache_test_" + std::to_string(::getpid()));
  stores.local.emplace(dir.string());
  EntryLookup found = stores.load_entry(key, 5);
  EXPECT_FALSE(found.entry);
  ASSERT_EQ(found.problems.size(), 1u);
  EXPECT_NE(found.problems[0].find("stored under another key (" + other + ")"), std::string::npos)
      << found.problems[0];
  EXPECT_FALSE(std::filesystem::exists(stores.local->path_of(key))) << "a refused remote entry is not kept";
  EXPECT_TRUE(stores.load_entry(other, 5).entry);
  std::filesystem::remove_all(dir);
}

TEST(CacheHttpTest, ABlobOverTheSizeLimitIsRefused) {
  test_http::TestHttpServer server(sha256_hex);
  const std::string key = "0123456789abcdef0123456789abcdef";
  std::string huge(kMaxEntryBytes + 1, 'x');
  std::string digest = sha256_hex(huge);
  server.set("/cas/" + digest, std::move(huge));
  server.set("/ac/" + sha256_hex(key), digest);
  StoredBytes got = HttpCache(server.url()).load_bytes(key);
  EXPECT_FALSE(got.bytes);
  EXPECT_EQ(got.problem, "its blob is over the limit of 67108864 bytes");
}

}  // namespace
}  // namespace facet::cache
