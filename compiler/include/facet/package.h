// .facetpkg: the versioned binary container that the compiler writes and the
// runtime reads. Readers validate every offset and length; a truncated or
// corrupted file is an error, never a crash.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "facet/diagnostics.h"
#include "facet/ir.h"
#include "facet/reflection.h"
#include "facet/result.h"
#include "facet/stage.h"
#include "facet/variants.h"

namespace facet::package {

inline constexpr uint32_t kFormatVersion = 1;

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
};

// Invariant: every PackageStage::blob < spirv_blobs.size().
struct Package {
  uint32_t version = kFormatVersion;
  std::string shader_name;
  std::vector<ir::Property> properties;
  std::vector<ir::Tag> subshader_tags;
  int lod = 0;
  std::string fallback;  // "" when none
  std::string custom_editor;
  std::vector<PackagePass> passes;
  std::vector<std::vector<uint32_t>> spirv_blobs;
};

// Deterministic bytes: the same Package gives the same bytes.
std::vector<uint8_t> write_package(const Package& package);
// `file` is used for diagnostics ("corrupt package: ..."); no spans into binary.
Result<Package> read_package(std::span<const uint8_t> bytes, Diagnostics& diags);
// A stable JSON view of the whole package (SPIR-V as word counts + hashes).
std::string package_to_json(const Package& package);

}  // namespace facet::package
