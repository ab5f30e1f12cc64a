// Runs the real facetc binary in a scratch folder and captures what it did.
#pragma once

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace facet::tools::testing {

namespace fs = std::filesystem;

struct FacetcRun {
  int exit_code = -1;
  std::string out, err;
};

inline std::string read_all(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

inline void write_all(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

inline std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// A fresh folder per test; facetc runs with it as the working directory.
class FacetcTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string(info->test_suite_name()) + "." + info->name();
    for (char& c : name) {
      if (c == '/') c = '_';
    }
    dir_ = fs::temp_directory_path() / ("facetc_test_" + std::to_string(::getpid())) / name;
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    if (!HasFailure()) fs::remove_all(dir_);
  }

  FacetcRun facetc(const std::vector<std::string>& args) const { return run(FACETC_PATH, args); }

#ifdef FACET_PATH
  // `facet render ARGS`. In a sanitizer build without LeakSanitizer's exit
  // check: the Vulkan loader unloads lavapipe before exit, so the driver's
  // leaks show as "<unknown module>" and tests/lsan.supp cannot match them;
  // the in-process render tests check facet's own memory.
  FacetcRun facet_render(const std::vector<std::string>& args) const {
    std::vector<std::string> all = {"render"};
    all.insert(all.end(), args.begin(), args.end());
    return run(FACET_PATH, all, "ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0 ");
  }
#endif

  // `program ARGS` in the scratch folder; `env` is a prefix of shell assignments.
  FacetcRun run(const std::string& program, const std::vector<std::string>& args, const std::string& env = "") const {
    std::string command = "cd " + shell_quote(dir_.string()) + " && " + env + shell_quote(program);
    for (const std::string& a : args) command += " " + shell_quote(a);
    command += " >stdout.txt 2>stderr.txt";
    int status = std::system(command.c_str());
    FacetcRun run;
    run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    run.out = read_all(dir_ / "stdout.txt");
    run.err = read_all(dir_ / "stderr.txt");
    fs::remove(dir_ / "stdout.txt");
    fs::remove(dir_ / "stderr.txt");
    return run;
  }

  // Files in the scratch folder, sorted.
  std::vector<std::string> files() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir_)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }

  static std::string example(const std::string& name) {
    return std::string(FACET_SOURCE_DIR) + "/examples/shaders/" + name;
  }

  fs::path dir_;
};

}  // namespace facet::tools::testing
