// Helpers of the facet brdf tests: run the command in-process, scratch files,
// PNG dimensions from the IHDR chunk.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "facet/runtime/brdf.h"

namespace facet::brdf::test {

struct CommandResult {
  int code = -1;
  std::string out, err;
};
inline CommandResult run_command(const std::vector<std::string>& args) {
  std::ostringstream out, err;
  int code = run_brdf_command(args, out, err);
  return {code, out.str(), err.str()};
}

// A folder of this process's scratch files (the tests of one binary share
// it), removed when the test program ends: MERL files are 35 MB each.
inline std::filesystem::path scratch_dir() {
  return std::filesystem::temp_directory_path() / ("facet_brdf_tests_" + std::to_string(::getpid()));
}
inline std::string scratch(const std::string& name) {
  std::filesystem::create_directories(scratch_dir());
  return (scratch_dir() / name).string();
}
struct ScratchCleanup : ::testing::Environment {
  void TearDown() override {
    std::error_code ignored;
    std::filesystem::remove_all(scratch_dir(), ignored);
  }
};
inline const bool kScratchCleanupRegistered = (::testing::AddGlobalTestEnvironment(new ScratchCleanup), true);

inline std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) return {};
  std::string bytes(size_t(in.tellg()), '\0');
  in.seekg(0);
  in.read(bytes.data(), std::streamsize(bytes.size()));
  return bytes;
}
inline void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
}

// (width, height) of a PNG, or (-1, -1) if it does not start like one.
inline std::pair<int, int> png_size(const std::string& path) {
  std::string b = read_bytes(path);
  if (b.size() < 24 || b.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0 || b.compare(12, 4, "IHDR") != 0) return {-1, -1};
  auto be32 = [&](size_t at) {
    return int((uint32_t(uint8_t(b[at])) << 24) | (uint32_t(uint8_t(b[at + 1])) << 16) |
               (uint32_t(uint8_t(b[at + 2])) << 8) | uint32_t(uint8_t(b[at + 3])));
  };
  return {be32(16), be32(20)};
}

}  // namespace facet::brdf::test
