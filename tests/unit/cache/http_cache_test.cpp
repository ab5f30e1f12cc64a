// The bazel-remote HTTP backend against a local server started by the test.
#include <gtest/gtest.h>

#include "facet/cache.h"
#include "unit/test_http_server.h"

namespace facet::cache {
namespace {

TEST(CacheHttpTest, StoresInTheBazelRemoteLayoutAndLoadsBack) {
  test_http::TestHttpServer server(sha256_hex);
  HttpCache remote(server.url() + "/");
  const std::string key = "0123456789abcdef0123456789abcdef", bytes = "entry bytes\0\x01\x02";
  EXPECT_FALSE(remote.load_bytes(key)) << "a miss";
  ASSERT_TRUE(remote.store_bytes(key, bytes));
  auto objects = server.objects();
  std::string digest = sha256_hex(bytes);
  EXPECT_EQ(objects.at("/cas/" + digest), bytes);
  EXPECT_EQ(objects.at("/ac/" + sha256_hex(key)), digest);
  auto back = remote.load_bytes(key);
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
  EXPECT_FALSE(remote.load_bytes(key)) << "a blob must hash to its name";
  server.set("/ac/" + sha256_hex(key), "not a digest");
  EXPECT_FALSE(remote.load_bytes(key));
  server.set("/ac/" + sha256_hex(key), sha256_hex("gone"));
  EXPECT_FALSE(remote.load_bytes(key));
}

TEST(CacheHttpTest, ServerDownIsAMissNotAFailure) {
  std::string url;
  {
    test_http::TestHttpServer server(sha256_hex);
    url = server.url();
  }  // stopped: its port is closed
  HttpCache remote(url, 2000);
  EXPECT_FALSE(remote.load_bytes("0123456789abcdef0123456789abcdef"));
  EXPECT_FALSE(remote.store_bytes("0123456789abcdef0123456789abcdef", "x"));
}

}  // namespace
}  // namespace facet::cache
