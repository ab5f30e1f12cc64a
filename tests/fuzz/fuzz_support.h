// What the fuzz targets share: the input as text, a private temporary
// folder for the loaders that only read files, and the -write_seeds=DIR
// flag of the targets that make their own seeds from real outputs.
#pragma once

#include <fmt/format.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>

namespace facet::fuzz {

inline std::string_view as_text(const uint8_t* data, size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// A folder of its own under $TMPDIR (or /tmp), made on first use and removed
// at exit. Targets write each input over the same file name in it, so a run
// never leaves more than one file behind, and never writes elsewhere.
class TempDir {
 public:
  static TempDir& get() {
    static TempDir dir;
    return dir;
  }
  const std::string& path() const { return path_; }
  std::string file(std::string_view name) const { return path_ + "/" + std::string(name); }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }

 private:
  TempDir() {
    const char* base = std::getenv("TMPDIR");
    std::string pattern = std::string(base && *base ? base : "/tmp") + "/facet-fuzz-XXXXXX";
    if (!mkdtemp(pattern.data())) {
      std::perror("facet fuzz: mkdtemp");
      std::abort();
    }
    path_ = pattern;
  }
  std::string path_;
};

// Writes `bytes` to `path` whole; aborts when it cannot (a broken fuzzing
// setup, not a finding about the input).
inline void write_bytes(const std::string& path, std::string_view bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), std::streamsize(bytes.size()));
  if (!out) {
    std::fprintf(stderr, "facet fuzz: cannot write %s\n", path.c_str());
    std::abort();
  }
}

// The DIR of a `-write_seeds=DIR` argument, if there is one.
inline std::optional<std::string> seed_dir(int argc, char** argv) {
  constexpr std::string_view kFlag = "-write_seeds=";
  for (int i = 1; i < argc; ++i) {
    std::string_view arg = argv[i];
    if (arg.starts_with(kFlag)) return std::string(arg.substr(kFlag.size()));
  }
  return std::nullopt;
}

inline void write_seed(const std::string& dir, const std::string& name, std::string_view bytes) {
  std::filesystem::create_directories(dir);
  write_bytes(dir + "/" + name, bytes);
  std::printf("wrote %s/%s (%zu bytes)\n", dir.c_str(), name.c_str(), bytes.size());
}

// A property the target checks beyond "no crash" failed: report and abort,
// so that libFuzzer keeps the input as a crash.
[[noreturn]] inline void property_failed(std::string_view what) {
  std::fprintf(stderr, "facet fuzz: property failed: %.*s\n", int(what.size()), what.data());
  std::abort();
}

}  // namespace facet::fuzz
