// facetc killed by SIGKILL at random moments, and several facetc processes
// writing one cache folder at once: whatever package exists afterwards is
// the clean build's, and the cache never hands a later build a wrong entry.
// docs/reliability.md describes the tests and what they cost.
#include <fmt/format.h>

#include <random>

#include "facetc_test_util.h"
#include "process_util.h"

namespace facet::tools::testing {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

// The kill moments come from this seed; FACET_CRASH_SEED picks another one
// (a failure prints the seed, the build's number and its delay).
unsigned crash_seed() {
  const char* text = std::getenv("FACET_CRASH_SEED");
  return text ? static_cast<unsigned>(std::stoul(text)) : 20261201u;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The files of `folder` that are not `keep`, by name.
std::vector<std::string> others_in(const fs::path& folder, const std::string& keep) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(folder)) {
    if (e.path().filename() != keep) names.push_back(e.path().filename().string());
  }
  return names;
}

class CrashSafetyTest : public FacetcTest {
 protected:
  std::vector<std::string> build_command(const std::string& shader, const fs::path& cache, const std::string& out,
                                         const std::vector<std::string>& extra = {}) const {
    std::vector<std::string> argv = {FACETC_PATH, example(shader), "--cache-dir", cache.string(), "-o", out};
    argv.insert(argv.end(), extra.begin(), extra.end());
    return argv;
  }

  // A clean build (no cache) of `shader` with `extra` options.
  std::string clean_package(const std::string& shader, const std::vector<std::string>& extra = {}) {
    std::vector<std::string> args = {example(shader), "--no-cache", "-o", "clean.facetpkg"};
    args.insert(args.end(), extra.begin(), extra.end());
    FacetcRun run = facetc(args);
    EXPECT_EQ(run.exit_code, 0) << run.err;
    std::string bytes = read_all(dir_ / "clean.facetpkg");
    fs::remove(dir_ / "clean.facetpkg");
    return bytes;
  }

  // Seconds of one uninterrupted build into `cache`.
  double timed_build(const std::string& shader, const fs::path& cache) {
    auto start = std::chrono::steady_clock::now();
    std::vector<std::string> argv = build_command(shader, cache, "timed.facetpkg", {"-j2"});
    Ended ended = wait_for(spawn_in(dir_, argv, dir_ / "timed.log").pid);
    EXPECT_TRUE(ended.exited && ended.code == 0) << read_all(dir_ / "timed.log");
    fs::remove(dir_ / "timed.facetpkg");
    return seconds_since(start);
  }
};

// 100 builds of PhongMultiLight.shader (9 variants, 10 distinct programs:
// small enough that 100 builds and rebuilds stay within a few minutes under
// the sanitizers, several programs so that kills land mid-build), each
// killed after a seeded random delay spread over the whole of a build: half
// into an empty cache folder (killed while compiling and storing), half into
// a full one (killed while reading hits and writing the package). After each
// kill: the output is absent or a complete package, the only other file
// beside it is the killed build's own temporary, and a rebuild from the same
// cache is byte-identical to the clean build and finds no corrupt entry.
TEST_F(CrashSafetyTest, HundredBuildsKilledAtRandomMomentsLeaveNoWrongPackage) {
  const std::string shader = "PhongMultiLight.shader";
  const std::string clean = clean_package(shader);
  const fs::path warm_cache = dir_ / "warm-cache";
  const double cold_seconds = timed_build(shader, dir_ / "timing-cache");
  timed_build(shader, warm_cache);  // fills it
  const double warm_seconds = timed_build(shader, warm_cache);
  fs::remove_all(dir_ / "timing-cache");
  fs::create_directories(dir_ / "out");
  const std::string out = "out/p.facetpkg";

  const unsigned seed = crash_seed();
  std::mt19937 random(seed);
  int killed = 0, temporaries_left = 0;
  for (int build = 0; build < 100; ++build) {
    const bool fresh = std::bernoulli_distribution(0.5)(random);
    const double span = fresh ? cold_seconds : warm_seconds;
    const auto delay = std::chrono::microseconds(
        std::uniform_int_distribution<long>(0, static_cast<long>(span * 1e6))(random));
    // Half the builds replace the last package, half write where none is.
    if (std::bernoulli_distribution(0.5)(random)) fs::remove(dir_ / out);
    const fs::path cache = fresh ? dir_ / fmt::format("fresh-cache-{}", build) : warm_cache;
    SCOPED_TRACE(fmt::format("seed {}, build {}: {} cache, SIGKILL after {} us (FACET_CRASH_SEED={} repeats it)", seed,
                             build, fresh ? "empty" : "full", delay.count(), seed));

    Spawned victim = spawn_in(dir_, build_command(shader, cache, out, {"-j2"}), dir_ / "killed.log");
    std::this_thread::sleep_for(delay);
    ::kill(victim.pid, SIGKILL);
    Ended ended = wait_for(victim.pid);
    if (ended.exited) {
      ASSERT_EQ(ended.code, 0) << read_all(dir_ / "killed.log");
    } else {
      ++killed;
    }
    fs::remove(dir_ / "killed.log");

    // The output is the old package, the new one or nothing: never a part.
    if (fs::exists(dir_ / out)) {
      ASSERT_TRUE(read_all(dir_ / out) == clean) << "a torn package at " << out;
    }
    for (const std::string& name : others_in(dir_ / "out", "p.facetpkg")) {
      ASSERT_THAT(name, ::testing::StartsWith(fmt::format("p.facetpkg.tmp.{}.", victim.pid)))
          << "only the killed build's own temporary may be left beside its output";
      fs::remove(dir_ / "out" / name);
      ++temporaries_left;
    }

    FacetcRun rebuild = facetc({example(shader), "--cache-dir", cache.string(), "--stats", "-o", out});
    ASSERT_EQ(rebuild.exit_code, 0) << rebuild.err;
    ASSERT_THAT(rebuild.err, Not(HasSubstr("corrupt"))) << "entries are renamed into place whole";
    ASSERT_TRUE(read_all(dir_ / out) == clean) << "the rebuild after the kill differs from the clean build";
    if (fresh) fs::remove_all(cache);
  }
  // Delays past the end of a build kill nothing; most must land inside one.
  EXPECT_GE(killed, 60) << "builds took " << cold_seconds << " s (empty cache) and " << warm_seconds << " s (full)";
  std::printf("[ crash    ] seed %u: %d of 100 builds killed mid-build (%.2f s empty cache, %.2f s full); "
              "%d output temporaries left by kills\n",
              seed, killed, cold_seconds, warm_seconds, temporaries_left);
}

// Four facetc processes at once into one cache folder, two of them building
// the same shader (racing on every key), two others beside them; rounds 0
// and 2 bring new keys (a -D that enters every key), so all four store at
// once, rounds 1 and 3 repeat them, so all four read. Every package is its
// clean build's, no build warns, and the repeated rounds compile nothing.
TEST_F(CrashSafetyTest, FourBuildersSharingOneCacheFolderProduceCleanPackages) {
  const std::vector<std::string> shaders = {"Keywords.shader", "Keywords.shader", "PhongMultiLight.shader",
                                            "TexturedAmbient.shader"};
  std::map<std::pair<std::string, int>, std::string> clean;
  for (int keys = 0; keys < 2; ++keys) {
    for (const std::string& shader : shaders) {
      if (!clean.count({shader, keys})) clean[{shader, keys}] = clean_package(shader, {fmt::format("-DROUND_{}", keys)});
    }
  }
  const fs::path cache = dir_ / "shared-cache";
  for (int round = 0; round < 4; ++round) {
    const int keys = round / 2;
    const bool repeated = round % 2 == 1;
    std::vector<Spawned> builders;
    for (size_t i = 0; i < shaders.size(); ++i) {
      builders.push_back(spawn_in(dir_,
                                  build_command(shaders[i], cache, fmt::format("r{}-{}.facetpkg", round, i),
                                                {"-j2", "--stats", fmt::format("-DROUND_{}", keys)}),
                                  dir_ / fmt::format("r{}-{}.log", round, i)));
    }
    for (size_t i = 0; i < shaders.size(); ++i) {
      SCOPED_TRACE(fmt::format("round {}, builder {} ({})", round, i, shaders[i]));
      Ended ended = wait_for(builders[i].pid);
      std::string log = read_all(dir_ / fmt::format("r{}-{}.log", round, i));
      EXPECT_TRUE(ended.exited && ended.code == 0) << log;
      EXPECT_THAT(log, Not(HasSubstr("warning"))) << log;
      if (repeated) {
        EXPECT_THAT(log, HasSubstr("/ remote hits 0 / compiled 0")) << log;
      }
      const std::string& expected = clean[{shaders[i], keys}];
      EXPECT_TRUE(read_all(dir_ / fmt::format("r{}-{}.facetpkg", round, i)) == expected);
    }
  }
  // Afterwards, one at a time: everything comes from the cache.
  for (const auto& [build, bytes] : clean) {
    FacetcRun last = facetc({example(build.first), "--cache-dir", cache.string(), "--stats",
                             fmt::format("-DROUND_{}", build.second), "-o", "last.facetpkg"});
    ASSERT_EQ(last.exit_code, 0) << last.err;
    EXPECT_THAT(last.err, HasSubstr("/ remote hits 0 / compiled 0")) << build.first << " " << build.second;
    EXPECT_THAT(last.err, HasSubstr("local hits"));
    EXPECT_TRUE(read_all(dir_ / "last.facetpkg") == bytes) << build.first << " " << build.second;
  }
}

}  // namespace
}  // namespace facet::tools::testing
