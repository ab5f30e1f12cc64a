// read_package: .facetpkg bytes -> Package, validating every byte on the way
// (docs/package-format.md, "Validation"). Steps: header, checksum, section
// table, string table, then each section through a bounded Decoder.
#include <xxhash.h>

#include <algorithm>
#include <array>
#include <cstdio>

#include "facet/package.h"
#include "codec.h"

namespace facet::package {
namespace {

using codec::DecodeContext;
using codec::Decoder;
using codec::SectionId;

// Minimum encoded sizes, which bound the counts a decoder accepts.
constexpr size_t kTagMinSize = 4 + 4;
constexpr size_t kValueSize = 1 + 4;
constexpr size_t kStateMinSize = 8 + 4 * 3 + 1;  // 8 absent optionals, 3 empty lists, no stencil
constexpr size_t kBlendMinSize = 4 + 1 + 2 * kValueSize + 2;
constexpr size_t kBlendOpMinSize = 4 + kValueSize + 1;
constexpr size_t kColorMaskMinSize = 4 + kValueSize;
constexpr size_t kAttributeMinSize = 4 + 4;
constexpr size_t kPropertyMinSize = 4 + 4 + 1 + 4 + 4 * 2 + 4 * 4 + 4;
constexpr size_t kPassMinSize = 4 + 4 + kStateMinSize;
constexpr size_t kKeywordSetMinSize = 1 + 1 + 1 + 4 + 4;
constexpr size_t kKeywordSpaceMinSize = 4 * 3;
using facet::codec::kReflectionMinSize;
// Format 1 stores each stage's reflection inline; format 2 an index into
// the reflection table at the start of the variants section.
constexpr size_t kStageMinSizeV1 = 1 + 4 + kReflectionMinSize;
constexpr size_t kStageMinSize = 1 + 4 + 4;
constexpr size_t kVariantMinSize = 4 * 3;

struct SectionRange {
  uint64_t offset = 0;
  uint64_t length = 0;
};
using SectionTable = std::array<SectionRange, codec::kSectionCount>;

std::string hex64(uint64_t v) {
  char buf[19];
  std::snprintf(buf, sizeof buf, "0x%016llx", static_cast<unsigned long long>(v));
  return buf;
}

// ---- Header and section table ---------------------------------------------

bool check_header(std::span<const uint8_t> bytes, DecodeContext& ctx, const ReadOptions& options) {
  if (bytes.size() < codec::kHeaderSize) {
    ctx.fail(bytes.size(), "file ends inside the " + std::to_string(codec::kHeaderSize) + "-byte header");
    return false;
  }
  if (!std::equal(codec::kMagic.begin(), codec::kMagic.end(), bytes.begin())) {
    ctx.fail(0, "bad magic (expected \"FACETPKG\"; not a facet package)");
    return false;
  }
  uint32_t version = codec::get_u32(bytes, codec::kVersionOffset);
  if (version > kFormatVersion) {
    ctx.failed = true;
    ctx.diags->add(DiagId::package_corrupt, SourceSpan{},
                   "package format version " + std::to_string(version) + " is newer than supported " +
                       std::to_string(kFormatVersion) + " (at byte offset " +
                       std::to_string(codec::kVersionOffset) + ")");
    return false;
  }
  if (version == 0) {
    ctx.fail(codec::kVersionOffset, "invalid format version 0");
    return false;
  }
  uint32_t flags = codec::get_u32(bytes, codec::kFlagsOffset);
  if (flags != 0) {
    ctx.fail(codec::kFlagsOffset, "unknown flags " + hex64(flags));
    return false;
  }
  uint64_t total = codec::get_u64(bytes, codec::kTotalSizeOffset);
  if (total != bytes.size()) {
    std::string what = total > bytes.size() ? "file truncated" : "trailing data after the package";
    ctx.fail(std::min<uint64_t>(total, bytes.size()),
             what + ": header says " + std::to_string(total) + " bytes, file has " + std::to_string(bytes.size()));
    return false;
  }
  if (options.verify_checksum) {
    uint64_t stored = codec::get_u64(bytes, codec::kChecksumOffset);
    uint64_t computed =
        XXH64(bytes.data() + codec::kHeaderSize, bytes.size() - codec::kHeaderSize, codec::kChecksumSeed);
    if (stored != computed) {
      ctx.fail(codec::kChecksumOffset, "checksum mismatch (stored " + hex64(stored) + ", computed " +
                                           hex64(computed) + ")");
      return false;
    }
  }
  return true;
}

// Every section present once, in SectionId order, each at the next 8-byte
// boundary with zero padding, the last one ending at the end of the file.
bool read_section_table(std::span<const uint8_t> bytes, DecodeContext& ctx, SectionTable& out) {
  Decoder d(bytes.subspan(codec::kHeaderSize), codec::kHeaderSize, ctx);
  uint64_t count_at = d.offset();
  uint32_t count = d.count(codec::kSectionEntrySize, "section");
  if (d.ok() && count != codec::kSectionCount) {
    d.fail_at(count_at, "expected " + std::to_string(codec::kSectionCount) + " sections, found " +
                            std::to_string(count));
  }
  if (d.ok() && d.u32() != 0) d.fail_at(d.offset() - 4, "reserved field is not zero");
  uint64_t end = codec::kHeaderSize + codec::kSectionTableHeaderSize + codec::kSectionEntrySize * codec::kSectionCount;
  for (uint32_t i = 0; i < codec::kSectionCount && d.ok(); ++i) {
    uint64_t entry_at = d.offset();
    uint32_t id = d.u32();
    uint32_t reserved = d.u32();
    uint64_t offset = d.u64();
    uint64_t length = d.u64();
    if (!d.ok()) break;
    std::string name(codec::section_name(SectionId(i + 1)));
    if (id != i + 1) {
      d.fail_at(entry_at, "section " + std::to_string(i) + " has id " + std::to_string(id) + ", expected " +
                              std::to_string(i + 1) + " ('" + name + "')");
    } else if (reserved != 0) {
      d.fail_at(entry_at + 4, "reserved field is not zero");
    } else if (offset != codec::align_up(end, codec::kSectionAlign)) {
      d.fail_at(entry_at + 8, "section '" + name + "' starts at " + std::to_string(offset) + ", expected " +
                                  std::to_string(codec::align_up(end, codec::kSectionAlign)));
    } else if (offset > bytes.size() || length > bytes.size() - offset) {
      d.fail_at(entry_at + 16, "section '" + name + "' (" + std::to_string(length) + " bytes at " +
                                   std::to_string(offset) + ") extends past the end of the file");
    } else {
      for (uint64_t p = end; p < offset; ++p) {
        if (bytes[p] != 0) {
          d.fail_at(p, "padding byte is not zero");
          break;
        }
      }
      out[i] = {offset, length};
      end = offset + length;
    }
  }
  if (d.ok() && end != bytes.size()) d.fail_at(end, std::to_string(bytes.size() - end) + " bytes after the last section");
  return d.ok();
}

Decoder section(std::span<const uint8_t> bytes, const SectionTable& table, SectionId id, DecodeContext& ctx) {
  const SectionRange& r = table[size_t(id) - 1];
  return Decoder(bytes.subspan(r.offset, r.length), r.offset, ctx);
}

// ---- Sections -------------------------------------------------------------

std::vector<std::string> decode_strings(Decoder& d) {
  uint32_t n = d.count(4, "string");
  std::vector<std::string> out;
  out.reserve(n);
  for (uint32_t i = 0; i < n && d.ok(); ++i) out.push_back(d.inline_string());
  return out;
}

std::vector<ir::Tag> decode_tags(Decoder& d) {
  uint32_t n = d.count(kTagMinSize, "tag");
  std::vector<ir::Tag> out(n);
  for (uint32_t i = 0; i < n && d.ok(); ++i) {
    out[i].key = d.str();
    out[i].value = d.str();
  }
  return out;
}

ir::StateValue decode_value(Decoder& d) {
  ir::StateValue v;
  uint64_t at = d.offset();
  bool is_property = d.enum_byte(1, "state value kind") == 1;
  std::string text = d.str();
  if (!is_property) {
    v.literal = std::move(text);
  } else if (text.empty()) {
    d.fail_at(at, "state value refers to a property with an empty name");
  } else {
    v.property = std::move(text);
  }
  return v;
}

std::optional<ir::StateValue> decode_optional(Decoder& d) {
  if (!d.boolean("optional presence flag") || !d.ok()) return std::nullopt;
  return decode_value(d);
}

ir::StencilState decode_stencil(Decoder& d) {
  ir::StencilState s;
  for (auto* v : {&s.ref, &s.read_mask, &s.write_mask, &s.comp, &s.pass, &s.fail, &s.zfail, &s.comp_back,
                  &s.pass_back, &s.fail_back, &s.zfail_back, &s.comp_front, &s.pass_front, &s.fail_front,
                  &s.zfail_front}) {
    *v = decode_optional(d);
  }
  return s;
}

void decode_targets(Decoder& d, ir::RenderState& s) {
  uint32_t n = d.count(kBlendMinSize, "blend state");
  s.blend.resize(n);
  for (uint32_t i = 0; i < n && d.ok(); ++i) {
    ir::BlendState& b = s.blend[i];
    b.render_target = d.i32();
    b.off = d.boolean("blend off flag");
    b.src = decode_value(d);
    b.dst = decode_value(d);
    b.src_alpha = decode_optional(d);
    b.dst_alpha = decode_optional(d);
  }
  n = d.count(kBlendOpMinSize, "blend op");
  s.blend_op.resize(n);
  for (uint32_t i = 0; i < n && d.ok(); ++i) {
    s.blend_op[i].render_target = d.i32();
    s.blend_op[i].color_op = decode_value(d);
    s.blend_op[i].alpha_op = decode_optional(d);
  }
  n = d.count(kColorMaskMinSize, "color mask");
  s.color_mask.resize(n);
  for (uint32_t i = 0; i < n && d.ok(); ++i) {
    s.color_mask[i].render_target = d.i32();
    s.color_mask[i].mask = decode_value(d);
  }
}

ir::RenderState decode_state(Decoder& d) {
  ir::RenderState s;
  for (auto* v : {&s.cull, &s.ztest, &s.zwrite, &s.alpha_to_mask, &s.zclip, &s.conservative, &s.offset_factor,
                  &s.offset_units}) {
    *v = decode_optional(d);
  }
  decode_targets(d, s);
  if (d.boolean("stencil presence flag") && d.ok()) s.stencil = decode_stencil(d);
  return s;
}

void decode_shader(Decoder& d, Package& p, uint32_t version) {
  p.shader_name = d.str();
  p.subshader_tags = decode_tags(d);
  p.lod = d.i32();
  p.fallback = d.str();
  p.custom_editor = d.str();
  if (version < 3) return;  // no build record: a whole build of unknown id
  p.build.shard_index = d.u32();
  uint64_t count_at = d.offset();
  p.build.shard_count = d.u32();
  p.build.build_id = d.u64();
  if (d.ok() && p.build.shard_index >= p.build.shard_count) {
    d.fail_at(count_at, "shard " + std::to_string(p.build.shard_index) + " of " +
                            std::to_string(p.build.shard_count) + " is no shard of its build");
  }
}

ir::Property decode_property(Decoder& d) {
  ir::Property p;
  p.name = d.str();
  p.display_name = d.str();
  p.type = ir::PropertyType(d.enum_byte(codec::kMaxPropertyType, "property type"));
  uint32_t n = d.count(kAttributeMinSize, "property attribute");
  p.attributes.resize(n);
  for (uint32_t i = 0; i < n && d.ok(); ++i) {
    p.attributes[i].name = d.str();
    p.attributes[i].args = d.strs("attribute argument");
  }
  p.range_min = d.f32();
  p.range_max = d.f32();
  for (float& f : p.default_value) f = d.f32();
  p.default_texture = d.str();
  return p;
}

std::vector<ir::Property> decode_properties(Decoder& d) {
  uint32_t n = d.count(kPropertyMinSize, "property");
  std::vector<ir::Property> out;
  out.reserve(n);
  for (uint32_t i = 0; i < n && d.ok(); ++i) out.push_back(decode_property(d));
  return out;
}

std::vector<PackagePass> decode_passes(Decoder& d, uint32_t version) {
  uint32_t n = d.count(kPassMinSize, "pass");
  std::vector<PackagePass> out(n);
  for (uint32_t i = 0; i < n && d.ok(); ++i) {
    out[i].name = d.str();
    out[i].tags = decode_tags(d);
    out[i].state = decode_state(d);
    out[i].source_index = i;
    if (version < 5) continue;  // format 5: the GrabPasses before the pass
    uint32_t grabs = d.count(4, "GrabPass texture");
    for (uint32_t g = 0; g < grabs && d.ok(); ++g) {
      uint64_t at = d.offset();
      std::string texture = d.str();
      if (d.ok() && texture.empty()) d.fail_at(at, "empty GrabPass texture name");
      out[i].grab_before.push_back(std::move(texture));
    }
    if (version >= 6) out[i].source_index = d.u32();  // format 6: the pass's index in its SubShader
  }
  return out;
}

// The per-pass sections (keywords, variants) start with the pass count.
bool expect_pass_count(Decoder& d, size_t min_size, std::string_view what, size_t passes) {
  uint64_t at = d.offset();
  uint32_t n = d.count(min_size, what);
  if (d.ok() && n != passes) {
    d.fail_at(at, std::string(what) + " count " + std::to_string(n) + " does not match the pass count " +
                      std::to_string(passes));
  }
  return d.ok();
}

// Format 4: keyword_rule pragmas, the curated combinations of Unity's
// shortcuts and their unreachable keywords, each checked against the sets.
void decode_selection_rules(Decoder& d, variants::KeywordSpace& space) {
  uint32_t rules = d.count(1 + 4 + 4, "keyword rule");
  for (uint32_t i = 0; i < rules && d.ok(); ++i) {
    variants::KeywordRule rule;
    rule.kind = variants::RuleKind(d.enum_byte(uint8_t(variants::RuleKind::implies), "keyword rule kind"));
    rule.keyword = d.str();
    rule.others = d.strs("keyword rule keyword");
    space.rules.push_back(std::move(rule));
  }
  uint32_t combinations = d.count(4 + 4 + 4, "keyword combination list");
  for (uint32_t i = 0; i < combinations && d.ok(); ++i) {
    variants::KeywordCombinations c;
    uint64_t at = d.offset();
    uint32_t sets = d.count(4, "combined keyword set");
    for (uint32_t k = 0; k < sets && d.ok(); ++k) {
      uint32_t set = d.u32();
      if (d.ok() && (set >= space.sets.size() || (!c.sets.empty() && set <= c.sets.back()))) {
        d.fail_at(at, "a combination names keyword set " + std::to_string(set) + " (sets ascending, below " +
                          std::to_string(space.sets.size()) + ")");
      }
      c.sets.push_back(set);
    }
    uint32_t choices = d.count(4, "keyword combination");
    for (uint32_t k = 0; k < choices && d.ok(); ++k) {
      at = d.offset();
      std::vector<uint32_t> choice = d.u32s("keyword choice");
      if (!d.ok()) break;
      bool fits = choice.size() == c.sets.size();
      for (size_t j = 0; fits && j < choice.size(); ++j) fits = choice[j] < space.sets[c.sets[j]].keywords.size();
      if (!fits) d.fail_at(at, "a keyword combination does not match its sets");
      c.choices.push_back(std::move(choice));
    }
    c.pragma = d.str();
    space.combinations.push_back(std::move(c));
  }
  space.unreachable_keywords = d.strs("unreachable keyword");
}

variants::KeywordSpace decode_keyword_space(Decoder& d, uint32_t version) {
  variants::KeywordSpace space;
  uint32_t n = d.count(kKeywordSetMinSize, "keyword set");
  space.sets.resize(n);
  for (uint32_t i = 0; i < n && d.ok(); ++i) {
    variants::KeywordSet& set = space.sets[i];
    set.directive = variants::KeywordDirective(d.enum_byte(codec::kMaxKeywordDirective, "keyword directive"));
    set.local = d.boolean("keyword set local flag");
    set.stages = d.enum_byte(kAllStages, "stage mask");
    set.keywords = d.strs("keyword");
    set.pragma = d.str();
  }
  space.dynamic_branch_keywords = d.strs("dynamic_branch keyword");
  space.skip_variants = d.strs("skip_variants keyword");
  if (version >= 4) decode_selection_rules(d, space);
  return space;
}

void decode_keywords(Decoder& d, std::vector<PackagePass>& passes, uint32_t version) {
  if (!expect_pass_count(d, kKeywordSpaceMinSize, "keyword space", passes.size())) return;
  for (size_t i = 0; i < passes.size() && d.ok(); ++i) passes[i].keywords = decode_keyword_space(d, version);
}

// The reflections a format-2 variants section shares between stages.
struct ReflectionTable {
  std::vector<StageReflection> reflections;
  std::vector<uint64_t> weights;  // reflection_weight of each, charged per reference
};

ReflectionTable decode_reflection_table(Decoder& d) {
  ReflectionTable table;
  uint32_t n = d.count(kReflectionMinSize, "reflection");
  table.reflections.reserve(n);
  for (uint32_t i = 0; i < n && d.ok(); ++i) {
    table.reflections.push_back(facet::codec::decode_reflection(d));
    table.weights.push_back(facet::codec::reflection_weight(table.reflections.back()));
  }
  return table;
}

StageReflection shared_reflection(Decoder& d, const ReflectionTable& table) {
  uint64_t at = d.offset();
  uint32_t index = d.u32();
  if (!d.ok()) return {};
  if (index >= table.reflections.size()) {
    d.fail_at(at, "reflection index " + std::to_string(index) + " out of range (table has " +
                      std::to_string(table.reflections.size()) + " reflections)");
    return {};
  }
  if (!d.charge(table.weights[index], "reflection references")) return {};
  return table.reflections[index];
}

PackageVariant decode_variant(Decoder& d, const ReflectionTable* table) {
  PackageVariant v;
  v.key.choice = d.u32s("key choice");
  v.keywords = d.strs("variant keyword");
  uint32_t n = d.count(table ? kStageMinSize : kStageMinSizeV1, "variant stage");
  v.stages.resize(n);
  for (uint32_t i = 0; i < n && d.ok(); ++i) {
    v.stages[i].stage = Stage(d.enum_byte(codec::kMaxStage, "stage"));
    v.stages[i].blob = d.u32();
    v.stages[i].reflection = table ? shared_reflection(d, *table) : facet::codec::decode_reflection(d);
  }
  return v;
}

void decode_variants(Decoder& d, std::vector<PackagePass>& passes, size_t blob_count, uint32_t version) {
  ReflectionTable table;
  if (version >= 2) table = decode_reflection_table(d);
  if (!expect_pass_count(d, 4, "variant list", passes.size())) return;
  for (PackagePass& pass : passes) {
    uint32_t n = d.count(kVariantMinSize, "variant");
    pass.variants.reserve(n);
    for (uint32_t i = 0; i < n && d.ok(); ++i) {
      uint64_t at = d.offset();
      pass.variants.push_back(decode_variant(d, version >= 2 ? &table : nullptr));
      const PackageVariant* previous = i ? &pass.variants[i - 1] : nullptr;
      std::string error = codec::check_variant(pass.keywords, pass.variants.back(), previous, blob_count);
      if (d.ok() && !error.empty()) d.fail_at(at, "pass '" + pass.name + "': " + error);
    }
    if (!d.ok()) return;
  }
}

std::vector<std::vector<uint32_t>> decode_blobs(Decoder& d) {
  uint32_t n = d.count(4, "SPIR-V blob");
  std::vector<std::vector<uint32_t>> out;
  out.reserve(n);
  for (uint32_t i = 0; i < n && d.ok(); ++i) out.push_back(d.u32s("SPIR-V word"));
  return out;
}

Package decode_sections(std::span<const uint8_t> bytes, const SectionTable& table, DecodeContext& ctx) {
  Package p;
  Decoder strings = section(bytes, table, SectionId::strings, ctx);
  ctx.strings = decode_strings(strings);
  strings.expect_end("strings");
  ctx.string_budget = codec::string_budget(bytes.size());

  Decoder shader = section(bytes, table, SectionId::shader, ctx);
  decode_shader(shader, p, codec::get_u32(bytes, codec::kVersionOffset));
  shader.expect_end("shader");
  Decoder properties = section(bytes, table, SectionId::properties, ctx);
  p.properties = decode_properties(properties);
  properties.expect_end("properties");
  Decoder passes = section(bytes, table, SectionId::passes, ctx);
  p.passes = decode_passes(passes, codec::get_u32(bytes, codec::kVersionOffset));
  passes.expect_end("passes");
  Decoder keywords = section(bytes, table, SectionId::keywords, ctx);
  decode_keywords(keywords, p.passes, codec::get_u32(bytes, codec::kVersionOffset));
  keywords.expect_end("keywords");
  // Blobs before variants, whose blob indices they bound.
  Decoder blobs = section(bytes, table, SectionId::blobs, ctx);
  p.spirv_blobs = decode_blobs(blobs);
  blobs.expect_end("blobs");
  Decoder variants = section(bytes, table, SectionId::variants, ctx);
  decode_variants(variants, p.passes, p.spirv_blobs.size(), codec::get_u32(bytes, codec::kVersionOffset));
  variants.expect_end("variants");
  return p;
}

}  // namespace

Result<Package> read_package(std::span<const uint8_t> bytes, Diagnostics& diags) {
  return read_package(bytes, diags, ReadOptions{});
}

Result<Package> read_package(std::span<const uint8_t> bytes, Diagnostics& diags, const ReadOptions& options) {
  DecodeContext ctx;
  ctx.diags = &diags;
  SectionTable table;
  if (!check_header(bytes, ctx, options) || !read_section_table(bytes, ctx, table)) {
    return failure("corrupt package");
  }
  Package p = decode_sections(bytes, table, ctx);
  if (ctx.failed) return failure("corrupt package");
  p.version = codec::get_u32(bytes, codec::kVersionOffset);
  return p;
}

}  // namespace facet::package
