// write_package: Package -> deterministic .facetpkg bytes. Each section is
// encoded into its own buffer (interning strings in encoding order), then the
// header, section table and sections are laid out and the checksum is set.
#include <xxhash.h>

#include <array>
#include <unordered_map>

#include "facet/package.h"
#include "codec.h"

namespace facet::package {
namespace {

using codec::Encoder;

void encode_tags(Encoder& e, const std::vector<ir::Tag>& tags) {
  e.count(tags.size());
  for (const ir::Tag& t : tags) {
    e.str(t.key);
    e.str(t.value);
  }
}

// kind:u8 (0 literal, 1 property) + text. A value with both set is written as
// a property, as StateValue::is_property() reads it.
void encode_value(Encoder& e, const ir::StateValue& v) {
  e.u8(v.is_property() ? 1 : 0);
  e.str(v.is_property() ? v.property : v.literal);
}

void encode_optional(Encoder& e, const std::optional<ir::StateValue>& v) {
  e.boolean(v.has_value());
  if (v) encode_value(e, *v);
}

void encode_stencil(Encoder& e, const ir::StencilState& s) {
  for (const auto* v : {&s.ref, &s.read_mask, &s.write_mask, &s.comp, &s.pass, &s.fail, &s.zfail, &s.comp_back,
                        &s.pass_back, &s.fail_back, &s.zfail_back, &s.comp_front, &s.pass_front, &s.fail_front,
                        &s.zfail_front}) {
    encode_optional(e, *v);
  }
}

void encode_state(Encoder& e, const ir::RenderState& s) {
  for (const auto* v : {&s.cull, &s.ztest, &s.zwrite, &s.alpha_to_mask, &s.zclip, &s.conservative, &s.offset_factor,
                        &s.offset_units}) {
    encode_optional(e, *v);
  }
  e.count(s.blend.size());
  for (const ir::BlendState& b : s.blend) {
    e.i32(b.render_target);
    e.boolean(b.off);
    encode_value(e, b.src);
    encode_value(e, b.dst);
    encode_optional(e, b.src_alpha);
    encode_optional(e, b.dst_alpha);
  }
  e.count(s.blend_op.size());
  for (const ir::BlendOpState& b : s.blend_op) {
    e.i32(b.render_target);
    encode_value(e, b.color_op);
    encode_optional(e, b.alpha_op);
  }
  e.count(s.color_mask.size());
  for (const ir::ColorMaskState& c : s.color_mask) {
    e.i32(c.render_target);
    encode_value(e, c.mask);
  }
  e.boolean(s.stencil.has_value());
  if (s.stencil) encode_stencil(e, *s.stencil);
}

void encode_shader(Encoder& e, const Package& p) {
  e.str(p.shader_name);
  encode_tags(e, p.subshader_tags);
  e.i32(p.lod);
  e.str(p.fallback);
  e.str(p.custom_editor);
  e.u32(p.build.shard_index);
  e.u32(p.build.shard_count);
  e.u64(p.build.build_id);
}

void encode_properties(Encoder& e, const std::vector<ir::Property>& props) {
  e.count(props.size());
  for (const ir::Property& p : props) {
    e.str(p.name);
    e.str(p.display_name);
    e.u8(uint8_t(p.type));
    e.count(p.attributes.size());
    for (const ir::PropertyAttribute& a : p.attributes) {
      e.str(a.name);
      e.strs(a.args);
    }
    e.f32(p.range_min);
    e.f32(p.range_max);
    for (float f : p.default_value) e.f32(f);
    e.str(p.default_texture);
  }
}

void encode_passes(Encoder& e, const std::vector<PackagePass>& passes) {
  e.count(passes.size());
  for (const PackagePass& p : passes) {
    e.str(p.name);
    encode_tags(e, p.tags);
    encode_state(e, p.state);
    e.count(p.grab_before.size());
    for (const std::string& texture : p.grab_before) e.str(texture);
    e.u32(p.source_index);
  }
}

void encode_keywords(Encoder& e, const std::vector<PackagePass>& passes) {
  e.count(passes.size());
  for (const PackagePass& p : passes) {
    const variants::KeywordSpace& space = p.keywords;
    e.count(space.sets.size());
    for (const variants::KeywordSet& set : space.sets) {
      e.u8(uint8_t(set.directive));
      e.boolean(set.local);
      e.u8(set.stages);
      e.strs(set.keywords);
      e.str(set.pragma);
    }
    e.strs(space.dynamic_branch_keywords);
    e.strs(space.skip_variants);
    // Format 4: what draw-time selection needs beyond the sets.
    e.count(space.rules.size());
    for (const variants::KeywordRule& rule : space.rules) {
      e.u8(uint8_t(rule.kind));
      e.str(rule.keyword);
      e.strs(rule.others);
    }
    e.count(space.combinations.size());
    for (const variants::KeywordCombinations& c : space.combinations) {
      e.count(c.sets.size());
      for (size_t set : c.sets) e.u32(uint32_t(set));
      e.count(c.choices.size());
      for (const std::vector<uint32_t>& choice : c.choices) e.u32s(choice);
      e.str(c.pragma);
    }
    e.strs(space.unreachable_keywords);
  }
}

// Stages that share a SPIR-V blob almost always share its reflection, so the
// variants section starts with a table of distinct reflections and each stage
// names one by index (format 2).
class ReflectionIndex {
 public:
  uint32_t index_of(const PackageStage& s) {
    auto [first, last] = by_blob_.equal_range(s.blob);
    for (auto it = first; it != last; ++it) {
      if (*unique_[it->second] == s.reflection) return it->second;
    }
    uint32_t index = uint32_t(unique_.size());
    unique_.push_back(&s.reflection);
    by_blob_.emplace(s.blob, index);
    return index;
  }
  const std::vector<const StageReflection*>& unique() const { return unique_; }

 private:
  std::vector<const StageReflection*> unique_;
  std::unordered_multimap<uint32_t, uint32_t> by_blob_;
};

void encode_variants(Encoder& e, const std::vector<PackagePass>& passes) {
  ReflectionIndex reflections;
  std::vector<uint32_t> stage_reflection;
  for (const PackagePass& p : passes) {
    for (const PackageVariant& v : p.variants) {
      for (const PackageStage& s : v.stages) stage_reflection.push_back(reflections.index_of(s));
    }
  }
  e.count(reflections.unique().size());
  for (const StageReflection* r : reflections.unique()) facet::codec::encode_reflection(e, *r);
  size_t next = 0;
  e.count(passes.size());
  for (const PackagePass& p : passes) {
    e.count(p.variants.size());
    for (const PackageVariant& v : p.variants) {
      e.u32s(v.key.choice);
      e.strs(v.keywords);
      e.count(v.stages.size());
      for (const PackageStage& s : v.stages) {
        e.u8(uint8_t(s.stage));
        e.u32(s.blob);
        e.u32(stage_reflection[next++]);
      }
    }
  }
}

void encode_blobs(Encoder& e, const std::vector<std::vector<uint32_t>>& blobs) {
  size_t bytes = 4;
  for (const std::vector<uint32_t>& blob : blobs) bytes += 4 + 4 * blob.size();
  e.bytes().reserve(bytes);  // the largest section by far: grown once, not by doubling
  e.count(blobs.size());
  for (const std::vector<uint32_t>& blob : blobs) e.u32s(blob);
}

void encode_strings(Encoder& e, const std::vector<std::string>& strings) {
  e.count(strings.size());
  for (const std::string& s : strings) {
    e.count(s.size());
    e.bytes().insert(e.bytes().end(), s.begin(), s.end());
  }
}

// Header + section table + sections (each at an 8-byte boundary, zero
// padding between), then the checksum over everything after the header.
std::vector<uint8_t> assemble(const std::array<std::vector<uint8_t>, codec::kSectionCount>& sections) {
  size_t table_end = codec::kHeaderSize + codec::kSectionTableHeaderSize + codec::kSectionEntrySize * sections.size();
  std::array<size_t, codec::kSectionCount> offsets{};
  size_t end = table_end;
  for (size_t i = 0; i < sections.size(); ++i) {
    offsets[i] = codec::align_up(end, codec::kSectionAlign);
    end = offsets[i] + sections[i].size();
  }
  std::vector<uint8_t> out(end, 0);
  std::copy(codec::kMagic.begin(), codec::kMagic.end(), out.begin());
  codec::put_u32(out, codec::kVersionOffset, kFormatVersion);
  codec::put_u32(out, codec::kFlagsOffset, 0);
  codec::put_u64(out, codec::kTotalSizeOffset, end);
  codec::put_u32(out, codec::kHeaderSize, uint32_t(sections.size()));
  for (size_t i = 0; i < sections.size(); ++i) {
    size_t entry = codec::kHeaderSize + codec::kSectionTableHeaderSize + i * codec::kSectionEntrySize;
    codec::put_u32(out, entry, uint32_t(i + 1));  // SectionId
    codec::put_u64(out, entry + 8, offsets[i]);
    codec::put_u64(out, entry + 16, sections[i].size());
    std::copy(sections[i].begin(), sections[i].end(), out.begin() + std::ptrdiff_t(offsets[i]));
  }
  uint64_t checksum = XXH64(out.data() + codec::kHeaderSize, out.size() - codec::kHeaderSize, codec::kChecksumSeed);
  codec::put_u64(out, codec::kChecksumOffset, checksum);
  return out;
}

}  // namespace

std::vector<uint8_t> write_package(const Package& package) {
  codec::StringTable strings;
  Encoder shader(strings), properties(strings), passes(strings), keywords(strings), variants(strings),
      blobs(strings), table(strings);
  encode_shader(shader, package);
  encode_properties(properties, package.properties);
  encode_passes(passes, package.passes);
  encode_keywords(keywords, package.passes);
  encode_variants(variants, package.passes);
  encode_blobs(blobs, package.spirv_blobs);
  encode_strings(table, strings.strings());
  // In SectionId order.
  return assemble({std::move(table.bytes()), std::move(shader.bytes()), std::move(properties.bytes()),
                   std::move(passes.bytes()), std::move(keywords.bytes()), std::move(variants.bytes()),
                   std::move(blobs.bytes())});
}

uint64_t build_id_of(std::string_view key) {
  uint64_t id = XXH64(key.data(), key.size(), 0);
  return id == 0 ? 1 : id;
}

}  // namespace facet::package
