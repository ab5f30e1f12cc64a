// .facetpkg: the versioned binary container that the compiler writes and the
// runtime reads. Readers validate every offset and length; a truncated or
// corrupted file is an error, never a crash.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "facet/diagnostics.h"
#include "facet/ir.h"
#include "facet/reflection.h"
#include "facet/result.h"
#include "facet/stage.h"
#include "facet/variants.h"

namespace facet::package {

// 3: the build record (shard i of N, build id); 2: reflections shared
// between stages (1: inline).
inline constexpr uint32_t kFormatVersion = 6;

struct PackageStage {
  Stage stage = Stage::vertex;
  uint32_t blob = 0;  // index into Package::spirv_blobs (identical SPIR-V stored once)
  StageReflection reflection;
};

struct PackageVariant {
  variants::VariantKey key;
  std::vector<std::string> keywords;  // all enabled keywords, set order
  std::vector<PackageStage> stages;   // in Stage order
};

struct PackagePass {
  std::string name;
  std::vector<ir::Tag> tags;
  ir::RenderState state;
  variants::KeywordSpace keywords;
  std::vector<PackageVariant> variants;  // sorted by key
  // The textures of the GrabPasses written between the package's pass
  // before this one (or the SubShader's start) and this one, in order: the
  // screen is copied into each before this pass draws (format 5; none before).
  std::vector<std::string> grab_before;
  // The pass's index in its SubShader, as facetc --pass, a variant
  // collection and a scene's image-effect `pass` count them (a build may keep
  // only some passes). Format 6; in older files, its position in the package.
  uint32_t source_index = 0;
};

// Which part of which build a package is, so that --merge can tell whether
// its shards make one whole build (docs/package-format.md, "Shards").
struct BuildRecord {
  uint32_t shard_index = 0;  // facetc --shard i/N: i
  uint32_t shard_count = 1;  // N; 1 for a whole (unsharded or merged) build
  // Identifies the build: facetc hashes the shader file's bytes, the
  // options that shape the code and the variants the whole build selects
  // (not --shard, -j or output paths), so shards of one build share it.
  // 0: unknown (files of format 1 and 2, packages written by library callers).
  uint64_t build_id = 0;
  bool operator==(const BuildRecord&) const = default;
};

// A BuildRecord::build_id for `key` (what identifies the build, spelled out
// by the caller): XXH64 of its bytes, never 0 (0 means unknown).
uint64_t build_id_of(std::string_view key);

// Invariant: every PackageStage::blob < spirv_blobs.size().
struct Package {
  uint32_t version = kFormatVersion;
  std::string shader_name;
  std::vector<ir::Property> properties;
  std::vector<ir::Tag> subshader_tags;
  int lod = 0;
  std::string fallback;  // "" when none
  std::string custom_editor;
  BuildRecord build;
  std::vector<PackagePass> passes;
  std::vector<std::vector<uint32_t>> spirv_blobs;
};

// Deterministic bytes: the same Package gives the same bytes. Layout in
// docs/package-format.md. Any Package can be written; read_package accepts
// the bytes back (and gives an equal Package, spans aside) exactly when
// validate_package accepts the Package and its strings stay within the
// reader's expansion limit (decoded string bytes at most 64 x file size +
// 1 MiB, and 1 GiB in all).
std::vector<uint8_t> write_package(const Package& package);

struct ReadOptions {
  // Off only for fuzzers and tests that reach the structural checks behind
  // the checksum; everything else is validated either way.
  bool verify_checksum = true;
};

// Validates every byte: magic, version, checksum, section bounds, counts,
// string and blob indices, enum values, and the invariants of validate_package.
// Errors are DiagId::package_corrupt diagnostics without a span ("corrupt
// package: <what> at byte offset N"); never throws. Package::version is the
// file's format version; SourceSpans read back as default spans.
Result<Package> read_package(std::span<const uint8_t> bytes, Diagnostics& diags);
Result<Package> read_package(std::span<const uint8_t> bytes, Diagnostics& diags, const ReadOptions& options);

// Checks the invariants that read_package enforces beyond the byte layout:
// blob indices in range, a build record with shard_index < shard_count,
// variants strictly sorted by key, each key has one
// choice per keyword set and each choice is in range (or kOffChoice), stages
// strictly in Stage order, block members nested at most 32 levels, no
// render-state value with both a literal and a property. Reports each problem
// as package_corrupt ("invalid package: ...") and returns false if any.
bool validate_package(const Package& package, Diagnostics& diags);

// Stores identical SPIR-V blobs once and drops unreferenced ones, remapping
// PackageStage::blob; blobs keep the order of their first reference.
void deduplicate_blobs(Package& package);

// Joins packages built as shards of one build (facetc --shard i/N) into the
// package the unsharded build gives, byte for byte: the shards must be
// exactly shards 0..N-1 of one build (one build id and shard count, each
// index once), from the same shader with the same passes and keyword
// spaces; their variants are united by key (a key in two shards must have
// identical stages) and the SPIR-V stored once in first-use order. A missing,
// repeated or foreign shard and other mismatches are package_merge_mismatch
// errors naming the shard (by `names[i]` when given, e.g. file names).
Result<Package> merge_packages(const std::vector<Package>& shards, Diagnostics& diags,
                               const std::vector<std::string>& names = {});

// A stable JSON view of the whole package (SPIR-V as word counts + hashes);
// keys in a fixed order, documented in docs/package-format.md.
std::string package_to_json(const Package& package);

}  // namespace facet::package
