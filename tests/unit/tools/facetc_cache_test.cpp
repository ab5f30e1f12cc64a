// facetc's compile cache across processes: a build killed mid-write leaves
// nothing the next build uses, and concurrent builds share one cache safely.
#include <signal.h>

#include <chrono>
#include <thread>

#include "facet/cache.h"
#include "facetc_test_util.h"
#include "unit/test_http_server.h"

namespace facet::tools::testing {
namespace {

using ::testing::HasSubstr;

TEST_F(FacetcTest, WarmBuildHitsTheCacheAndPrintsIt) {
  ASSERT_EQ(facetc({example("Keywords.shader"), "--no-cache", "-o", "ref.facetpkg"}).exit_code, 0);
  FacetcRun cold = facetc({example("Keywords.shader"), "--cache-dir", "cache", "--stats", "-o", "cold.facetpkg"});
  ASSERT_EQ(cold.exit_code, 0) << cold.err;
  EXPECT_THAT(cold.err, HasSubstr("cache: local hits 0 / remote hits 0 / compiled 50"));
  FacetcRun warm = facetc({example("Keywords.shader"), "--cache-dir", "cache", "--stats", "-o", "warm.facetpkg"});
  ASSERT_EQ(warm.exit_code, 0) << warm.err;
  EXPECT_THAT(warm.err, HasSubstr("cache: local hits 50 / remote hits 0 / compiled 0"));
  EXPECT_TRUE(read_all(dir_ / "ref.facetpkg") == read_all(dir_ / "cold.facetpkg"));
  EXPECT_TRUE(read_all(dir_ / "ref.facetpkg") == read_all(dir_ / "warm.facetpkg"));
}

TEST_F(FacetcTest, BuildKilledMidWriteLeavesNoUsableCorruptEntry) {
  ASSERT_EQ(facetc({example("Keywords.shader"), "-o", "ref.facetpkg"}).exit_code, 0);
  std::string reference = read_all(dir_ / "ref.facetpkg");
  // Kill builds at several moments, each into the same cache.
  for (int delay_ms : {20, 60, 120, 250}) {
    std::string command = "cd " + shell_quote(dir_.string()) + " && { " + shell_quote(FACETC_PATH) + " " +
                          shell_quote(example("Keywords.shader")) +
                          " -j2 --cache-dir cache -o killed.facetpkg >/dev/null 2>&1 & echo $! > pid; }";
    ASSERT_EQ(std::system(command.c_str()), 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms));
    pid_t pid = std::stoi(read_all(dir_ / "pid"));
    ::kill(pid, SIGKILL);
    std::system(("while kill -0 " + std::to_string(pid) + " 2>/dev/null; do sleep 0.01; done").c_str());
  }
  FacetcRun next = facetc({example("Keywords.shader"), "--cache-dir", "cache", "--stats", "-o", "next.facetpkg"});
  ASSERT_EQ(next.exit_code, 0) << next.err;
  EXPECT_EQ(next.err.find("corrupt"), std::string::npos) << "renames are atomic: no torn entry exists\n" << next.err;
  EXPECT_TRUE(read_all(dir_ / "next.facetpkg") == reference);
  // Leftover temporaries of the killed builds are never read as entries.
  FacetcRun warm = facetc({example("Keywords.shader"), "--cache-dir", "cache", "--stats", "-o", "warm.facetpkg"});
  EXPECT_THAT(warm.err, HasSubstr("/ compiled 0"));
  EXPECT_TRUE(read_all(dir_ / "warm.facetpkg") == reference);
}

TEST_F(FacetcTest, ConcurrentBuildsIntoOneCacheAreCorrect) {
  ASSERT_EQ(facetc({example("Keywords.shader"), "-o", "ref.facetpkg"}).exit_code, 0);
  std::string both = "cd " + shell_quote(dir_.string()) + " && { ";
  for (int i = 0; i < 3; ++i) {
    both += shell_quote(FACETC_PATH) + " " + shell_quote(example("Keywords.shader")) +
            " -j2 --cache-dir cache -o p" + std::to_string(i) + ".facetpkg 2>err" + std::to_string(i) + " & ";
  }
  both += "wait; }";
  ASSERT_EQ(std::system(both.c_str()), 0);
  for (int i = 0; i < 3; ++i) {
    EXPECT_TRUE(read_all(dir_ / ("p" + std::to_string(i) + ".facetpkg")) == read_all(dir_ / "ref.facetpkg")) << i;
    EXPECT_EQ(read_all(dir_ / ("err" + std::to_string(i))), "") << i;
  }
}

TEST_F(FacetcTest, RemoteCacheServesASecondMachine) {
  test_http::TestHttpServer server(cache::sha256_hex);
  FacetcRun first = facetc({example("Keywords.shader"), "--remote-cache", server.url(), "--cache-dir", "a", "--stats",
                            "-o", "a.facetpkg"});
  ASSERT_EQ(first.exit_code, 0) << first.err;
  EXPECT_THAT(first.err, HasSubstr("remote hits 0 / compiled 50"));
  FacetcRun second = facetc({example("Keywords.shader"), "--remote-cache", server.url(), "--cache-dir", "b",
                             "--stats", "-o", "b.facetpkg"});
  ASSERT_EQ(second.exit_code, 0) << second.err;
  EXPECT_THAT(second.err, HasSubstr("local hits 0 / remote hits 50 / compiled 0"));
  EXPECT_TRUE(read_all(dir_ / "a.facetpkg") == read_all(dir_ / "b.facetpkg"));
  FacetcRun down = facetc({example("Unlit.shader"), "--remote-cache", "http://127.0.0.1:1", "-o", "c.facetpkg"});
  EXPECT_EQ(down.exit_code, 0) << "an unreachable server never fails a build";
}

}  // namespace
}  // namespace facet::tools::testing
