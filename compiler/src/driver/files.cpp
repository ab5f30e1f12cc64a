// File output for the driver (atomic writes), the stdlib's place and the version.
#include <fmt/format.h>

#include "files.h"
#include "facet/support/atomic_file.h"
#include "facet/compiler.h"

namespace facet {

Result<void> write_file_atomically(const std::string& path, std::string_view bytes, Diagnostics& diags) {
  if (Result<void, std::string> written = support::write_file_atomically(path, bytes); !written) {
    diags.add(DiagId::io_cannot_write, {}, fmt::format("cannot write '{}': {}", path, written.error()));
    return failure("cannot write");
  }
  return {};
}

std::string default_stdlib_dir() { return backend::default_stdlib_dir(); }

std::string version_string() { return fmt::format("facet {} (glslang 12, SPIRV-Tools, SPIRV-Cross)", FACET_VERSION); }

}  // namespace facet
