// Byte-level encoding of .facetpkg (docs/package-format.md): the layout
// constants, a little-endian Encoder that interns strings, and a bounded
// Decoder that never reads past its span, never allocates more than the
// input can justify, and records the first error with its byte offset.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "facet/support/binary_codec.h"
#include "facet/diagnostics.h"
#include "facet/ir.h"
#include "facet/package.h"
#include "facet/reflection.h"
#include "facet/variants.h"

namespace facet::package::codec {

// The generic byte codec (common/binary_codec.h) under the package's names.
using facet::codec::align_up;
using facet::codec::DecodeContext;
using facet::codec::Decoder;
using facet::codec::Encoder;
using facet::codec::get_u32;
using facet::codec::get_u64;
using facet::codec::kMaxMemberDepth;
using facet::codec::kMaxResourceKind;
using facet::codec::kMaxStage;
using facet::codec::put_u32;
using facet::codec::put_u64;
using facet::codec::StringTable;

// ---- Layout ---------------------------------------------------------------

inline constexpr std::array<uint8_t, 8> kMagic = {'F', 'A', 'C', 'E', 'T', 'P', 'K', 'G'};
// magic[8] version:u32 flags:u32 total_size:u64 checksum:u64
inline constexpr size_t kHeaderSize = 32;
inline constexpr size_t kVersionOffset = 8;
inline constexpr size_t kFlagsOffset = 12;
inline constexpr size_t kTotalSizeOffset = 16;
inline constexpr size_t kChecksumOffset = 24;
// The section table starts at kHeaderSize: count:u32 reserved:u32, then
// `count` entries of id:u32 reserved:u32 offset:u64 length:u64.
inline constexpr size_t kSectionTableHeaderSize = 8;
inline constexpr size_t kSectionEntrySize = 24;
inline constexpr size_t kSectionAlign = 8;
// Seed of the xxHash64 checksum over bytes [kHeaderSize, total_size).
inline constexpr uint64_t kChecksumSeed = 0;

// In file order; every section is present exactly once, in this order.
enum class SectionId : uint32_t { strings = 1, shader, properties, passes, keywords, variants, blobs };
inline constexpr uint32_t kSectionCount = 7;
std::string_view section_name(SectionId id);

// Strings expand through references; decoded string bytes are limited to
// min(kStringBudgetFactor * file size + kStringBudgetBase, kStringBudgetMax).
inline constexpr uint64_t kStringBudgetFactor = 64;
inline constexpr uint64_t kStringBudgetBase = uint64_t(1) << 20;
inline constexpr uint64_t kStringBudgetMax = uint64_t(1) << 30;
inline uint64_t string_budget(uint64_t file_size) {
  uint64_t budget = kStringBudgetFactor * file_size + kStringBudgetBase;
  return budget < kStringBudgetMax ? budget : kStringBudgetMax;
}

// Largest valid value of each enum stored as a byte.
inline constexpr uint8_t kMaxPropertyType = uint8_t(ir::PropertyType::tex_any);
inline constexpr uint8_t kMaxKeywordDirective = 2;  // dynamic_branch

// ---- Shared pieces --------------------------------------------------------

// Invariant checks shared by read_package and validate_package: "" when
// fine, otherwise what is wrong. `previous` is the variant before `v` in its
// pass (nullptr for the first).
std::string check_variant(const variants::KeywordSpace& space, const PackageVariant& v,
                          const PackageVariant* previous, size_t blob_count);

}  // namespace facet::package::codec
