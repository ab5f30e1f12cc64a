// Arbitrary bytes as a .facetpkg through the package reader, once as the
// runtime reads files (checksum verified) and once with the checksum check
// off, so that mutations reach the section, string, blob and reflection
// decoders behind it. A package that reads must write and read back (the
// round trip write_package documents), and print as JSON.
//
//   fuzz_package -write_seeds=DIR   writes packages compiled from examples/
#include <span>

#include "facet/package.h"
#include "fuzz_support.h"
#include "real_package.h"

namespace {

using namespace facet;

void write_seeds(const std::string& dir) {
  for (const char* name : {"VertexColor", "Unlit", "Diffuse"}) {
    CompiledShader compiled = fuzz::compile_example(std::string("examples/shaders/") + name + ".shader");
    std::vector<uint8_t> bytes = package::write_package(compiled.package);
    fuzz::write_seed(dir, std::string(name) + ".facetpkg",
                     std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
  }
}

void check_round_trip(const package::Package& package) {
  std::vector<uint8_t> bytes = package::write_package(package);
  Diagnostics diags;
  auto again = package::read_package(bytes, diags);
  if (!again) fuzz::property_failed("a package that was read does not read back after write_package");
  if (package::write_package(*again) != bytes) fuzz::property_failed("write(read(write(p))) != write(p)");
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
  if (auto dir = fuzz::seed_dir(*argc, *argv)) {
    write_seeds(*dir);
    std::exit(0);
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::span<const uint8_t> bytes(data, size);
  {
    Diagnostics diags;
    (void)package::read_package(bytes, diags);
  }
  Diagnostics diags;
  auto package = package::read_package(bytes, diags, {.verify_checksum = false});
  if (!package) return 0;
  (void)package::package_to_json(*package);
  check_round_trip(*package);
  return 0;
}
