// Arbitrary bytes as a compile-cache entry and as an include manifest
// (facet/cache.h), each decoded twice: as stored, and with its checksum made
// right, so that mutations reach the layout and reflection decoders behind
// it. An entry or manifest that decodes must encode and decode back equal.
//
//   fuzz_cache -write_seeds=DIR   writes entries and manifests made from a
//                                 compiled example shader
#include <xxhash.h>

#include "facet/cache.h"
#include "fuzz_support.h"
#include "real_package.h"

namespace {

using namespace facet;

// Every seed is stored under this key, so that the key binding passes and
// mutations of the rest are decoded.
const std::string kKey = "fuzz0000000000000000000000000000";
// The checksum seed of the entry and manifest formats (docs/cache.md).
constexpr uint64_t kChecksumSeed = 0x66616365745f6361ull;  // "facet_ca"

std::string with_entry_checksum(std::string_view bytes) {
  if (bytes.size() < 8) return std::string(bytes);
  std::string out(bytes.substr(0, bytes.size() - 8));
  uint64_t sum = XXH64(out.data(), out.size(), kChecksumSeed);
  for (int i = 0; i < 8; ++i) out += char((sum >> (8 * i)) & 0xff);
  return out;
}

std::string with_manifest_checksum(std::string_view bytes) {
  std::string out(bytes.substr(0, std::min(bytes.size(), bytes.rfind("check "))));
  return out + fmt::format("check {:016x}\n", XXH64(out.data(), out.size(), kChecksumSeed));
}

void check_entry(std::string_view bytes) {
  auto entry = cache::decode_entry(bytes, kKey);
  if (!entry) return;
  auto again = cache::decode_entry(cache::encode_entry(kKey, *entry), kKey);
  if (!again) fuzz::property_failed("a decoded cache entry does not decode after encode_entry");
  if (again->spirv != entry->spirv || again->included_files != entry->included_files ||
      again->token_hash != entry->token_hash) {
    fuzz::property_failed("a cache entry changed through encode and decode");
  }
}

void check_manifest(std::string_view bytes) {
  auto manifest = cache::decode_manifest(bytes, kKey);
  if (!manifest) return;
  auto again = cache::decode_manifest(cache::encode_manifest(kKey, *manifest), kKey);
  if (!again) fuzz::property_failed("a decoded include manifest does not decode after encode_manifest");
  if (again->entry_key != manifest->entry_key || again->token_hash != manifest->token_hash ||
      again->files != manifest->files) {
    fuzz::property_failed("an include manifest changed through encode and decode");
  }
}

void write_seeds(const std::string& dir) {
  CompiledShader compiled = fuzz::compile_example("examples/shaders/VertexColor.shader");
  const package::PackageVariant& variant = compiled.package.passes.at(0).variants.at(0);
  int n = 0;
  for (const package::PackageStage& stage : variant.stages) {
    cache::CacheEntry entry{{.spirv = compiled.package.spirv_blobs.at(stage.blob),
                             .reflection = stage.reflection,
                             .included_files = {"Example.shader", "UnityCG.cginc"}},
                            /*token_hash=*/0x0123456789abcdefull};
    fuzz::write_seed(dir, fmt::format("entry{}.bin", n++), cache::encode_entry(kKey, entry));
  }
  cache::IncludeManifest manifest{.entry_key = "entry0000", .token_hash = 0x0123456789abcdefull};
  for (const std::string& file : compiled.dependencies) {
    std::string name = std::filesystem::path(file).filename().string();  // no machine's paths in seeds
    manifest.files.emplace_back(name, XXH3_64bits(name.data(), name.size()));
  }
  fuzz::write_seed(dir, "manifest.txt", cache::encode_manifest(kKey, manifest));
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
  std::string_view bytes = fuzz::as_text(data, size);
  check_entry(bytes);
  check_manifest(bytes);
  check_entry(with_entry_checksum(bytes));
  check_manifest(with_manifest_checksum(bytes));
  return 0;
}
