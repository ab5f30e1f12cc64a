// File input and output for the driver: bounded reads, atomic writes.
#include <fmt/format.h>

#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

#include "files.h"
#include "facet/compiler.h"

namespace facet {
namespace fs = std::filesystem;

Result<std::string> read_file(const std::string& path, uint64_t max_bytes, Diagnostics& diags) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) {
    diags.add(DiagId::io_cannot_read, {}, fmt::format("'{}' is a directory", path));
    return failure("directory");
  }
  auto size = fs::file_size(path, ec);
  if (ec) {
    diags.add(DiagId::io_cannot_read, {}, fmt::format("cannot open '{}': {}", path, ec.message()));
    return failure("cannot open");
  }
  if (size > max_bytes) {
    diags.add(DiagId::io_too_large, {},
              fmt::format("'{}' is {} bytes; the limit is {} bytes", path, size, max_bytes));
    return failure("too large");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    diags.add(DiagId::io_cannot_read, {}, fmt::format("cannot open '{}'", path));
    return failure("cannot open");
  }
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

Result<void> write_file_atomically(const std::string& path, std::string_view bytes, Diagnostics& diags) {
  fs::path target(path);
  fs::path temp = target;
  // Unique per process and call, so concurrent writers never share a temp file.
  static std::atomic<uint64_t> counter{0};
  temp += fmt::format(".tmp.{}.{}", ::getpid(), counter++);
  {
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    if (!out) {
      diags.add(DiagId::io_cannot_write, {}, fmt::format("cannot write '{}'", path));
      return failure("cannot write");
    }
    out.write(bytes.data(), std::streamsize(bytes.size()));
    out.flush();
    if (!out) {
      out.close();
      std::error_code ignore;
      fs::remove(temp, ignore);
      diags.add(DiagId::io_cannot_write, {}, fmt::format("cannot write '{}'", path));
      return failure("cannot write");
    }
  }
  std::error_code ec;
  fs::rename(temp, target, ec);
  if (ec) {
    fs::remove(temp, ec);
    diags.add(DiagId::io_cannot_write, {}, fmt::format("cannot write '{}'", path));
    return failure("cannot write");
  }
  return {};
}

std::string default_stdlib_dir() { return backend::default_stdlib_dir(); }

std::string version_string() { return fmt::format("facet {} (glslang 12, SPIRV-Tools, SPIRV-Cross)", FACET_VERSION); }

}  // namespace facet
