#include "facet/package_file.h"

#include <span>

#include "facet/support/read_file.h"

namespace facet {

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
