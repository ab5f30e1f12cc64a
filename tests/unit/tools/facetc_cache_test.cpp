// facetc's compile cache across processes: a build killed mid-write leaves
// nothing the next build uses, and concurrent builds share one cache safely.
#include <signal.h>

#include <chrono>
#include <thread>

#include "facetc_test_util.h"

namespace facet::tools::testing {
namespace {

using ::testing::HasSubstr;

TEST_F(FacetcTest, WarmBuildHitsTheCacheAndPrintsIt) {
  ASSERT_EQ(facetc({example("Keywords.shader"), "--no-cache", "-o", "ref.facetpkg"}).exit_code, 0);
  FacetcRun cold = facetc({example("Keywords.shader"), "--cache-dir", "cache", "--stats", "-o", "cold.facetpkg"});
  ASSERT_EQ(cold.exit_code, 0) << cold.err;
  EXPECT_THAT(cold.err, HasSubstr("cache: local hits 0 / compiled 50"));
  FacetcRun warm = facetc({example("Keywords.shader"), "--cache-dir", "cache", "--stats", "-o", "warm.facetpkg"});
  ASSERT_EQ(warm.exit_code, 0) << warm.err;
  EXPECT_THAT(warm.err, HasSubstr("cache: local hits 50 / compiled 0"));
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

}  // namespace
}  // namespace facet::tools::testing
