#include "facet/support/read_file.h"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

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

}  // namespace facet
