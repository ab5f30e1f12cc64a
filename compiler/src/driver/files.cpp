// File input and output for the driver: bounded reads, atomic writes.
#include <fmt/format.h>


#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

#include "files.h"
#include "facet/support/atomic_file.h"
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
  if (Result<void, std::string> written = support::write_file_atomically(path, bytes); !written) {
    diags.add(DiagId::io_cannot_write, {}, fmt::format("cannot write '{}': {}", path, written.error()));
    return failure("cannot write");
  }
  return {};
}

std::string default_stdlib_dir() { return backend::default_stdlib_dir(); }

std::string version_string() { return fmt::format("facet {} (glslang 12, SPIRV-Tools, SPIRV-Cross)", FACET_VERSION); }

Result<package::Package> read_package_file(const std::string& path, Diagnostics& diags) {
  auto bytes = read_file(path, kMaxPackageBytes, diags);
  FACET_TRY(bytes);
  Diagnostics read;  // only the reader's messages get the file's name
  auto pkg = package::read_package(std::span(reinterpret_cast<const uint8_t*>(bytes->data()), bytes->size()), read);
  for (Diagnostic& d : read.mutable_all()) {
    if (!pkg) d.message = path + ": " + d.message;
    diags.push(std::move(d));
  }
  if (!pkg) return failure("corrupt package");
  return pkg;
}

}  // namespace facet
