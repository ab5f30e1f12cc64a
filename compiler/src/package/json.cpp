// package_to_json: a stable, readable view of a Package. Keys are in a fixed
// order (ordered_json built in code order); unset optional render state is
// omitted; SPIR-V blobs appear as word count + xxh64 of their little-endian
// bytes. Floats print as the shortest text that reads back as the same float
// (non-finite ones as "nan", "inf", "-inf"); a key choice of kOffChoice as "off".
#include <xxhash.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "facet/package.h"
#include "facet/reflection_json.h"
#include "facet/support/state_json.h"

namespace facet::package {
namespace {

using Json = nlohmann::ordered_json;

Json number(float f) {
  if (std::isnan(f)) return "nan";
  if (std::isinf(f)) return f > 0 ? "inf" : "-inf";
  // float -> shortest decimal -> double, so 0.1f prints as 0.1 rather than
  // 0.10000000149011612.
  char buf[32];
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, f);
  double d = f;
  if (ec == std::errc()) std::from_chars(buf, end, d);
  return d;
}

std::string_view directive_text(variants::KeywordDirective d) {
  switch (d) {
    case variants::KeywordDirective::multi_compile: return "multi_compile";
    case variants::KeywordDirective::shader_feature: return "shader_feature";
    case variants::KeywordDirective::dynamic_branch: return "dynamic_branch";
  }
  return "unknown";
}

Json stage_mask(StageMask mask) {
  Json out = Json::array();
  for (int i = 0; i < kStageCount; ++i) {
    if (mask & stage_bit(Stage(i))) out.push_back(stage_name(Stage(i)));
  }
  return out;
}

Json property(const ir::Property& p) {
  Json attributes = Json::array();
  for (const ir::PropertyAttribute& a : p.attributes) attributes.push_back(Json{{"name", a.name}, {"args", a.args}});
  Json defaults = Json::array();
  for (float f : p.default_value) defaults.push_back(number(f));
  return Json{{"name", p.name},
              {"display_name", p.display_name},
              {"type", property_type_name(p.type)},
              {"attributes", std::move(attributes)},
              {"range", Json::array({number(p.range_min), number(p.range_max)})},
              {"default", std::move(defaults)},
              {"default_texture", p.default_texture}};
}

Json keyword_space(const variants::KeywordSpace& space) {
  Json sets = Json::array();
  for (const variants::KeywordSet& s : space.sets) {
    sets.push_back(Json{{"directive", directive_text(s.directive)},
                        {"pragma", s.pragma},
                        {"local", s.local},
                        {"stages", stage_mask(s.stages)},
                        {"keywords", s.keywords}});
  }
  return Json{{"sets", std::move(sets)},
              {"dynamic_branch", space.dynamic_branch_keywords},
              {"skip_variants", space.skip_variants}};
}

Json variant(const PackageVariant& v) {
  Json stages = Json::array();
  for (const PackageStage& s : v.stages) {
    stages.push_back(Json{{"stage", stage_name(s.stage)}, {"blob", s.blob}, {"reflection", reflection_to_ordered_json(s.reflection)}});
  }
  Json key = Json::array();
  for (uint32_t c : v.key.choice) {
    if (c == variants::kOffChoice) {
      key.push_back("off");
    } else {
      key.push_back(c);
    }
  }
  return Json{{"key", std::move(key)}, {"keywords", v.keywords}, {"stages", std::move(stages)}};
}

Json pass(const PackagePass& p) {
  Json list = Json::array();
  for (const PackageVariant& v : p.variants) list.push_back(variant(v));
  Json out{{"name", p.name},
           {"index", p.source_index},
           {"tags", tags_json(p.tags)},
           {"state", render_state_json(p.state)},
           {"keywords", keyword_space(p.keywords)},
           {"variants", std::move(list)}};
  if (!p.grab_before.empty()) out["grab_before"] = p.grab_before;
  return out;
}

Json blob(const std::vector<uint32_t>& words) {
  std::vector<uint8_t> bytes;
  bytes.reserve(words.size() * 4);
  for (uint32_t w : words) {
    for (int i = 0; i < 4; ++i) bytes.push_back(uint8_t(w >> (8 * i)));
  }
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(XXH64(bytes.data(), bytes.size(), 0)));
  return Json{{"words", words.size()}, {"xxh64", hex}};
}

Json build_record(const BuildRecord& b) {
  char id[17];
  std::snprintf(id, sizeof id, "%016llx", static_cast<unsigned long long>(b.build_id));
  return Json{{"shard", b.shard_index}, {"shards", b.shard_count}, {"id", id}};
}

}  // namespace

std::string package_to_json(const Package& package) {
  Json props = Json::array();
  for (const ir::Property& p : package.properties) props.push_back(property(p));
  Json passes = Json::array();
  for (const PackagePass& p : package.passes) passes.push_back(pass(p));
  Json blobs = Json::array();
  for (const std::vector<uint32_t>& b : package.spirv_blobs) blobs.push_back(blob(b));
  Json out{{"format_version", package.version},
           {"shader", Json{{"name", package.shader_name},
                           {"lod", package.lod},
                           {"fallback", package.fallback},
                           {"custom_editor", package.custom_editor},
                           {"tags", tags_json(package.subshader_tags)},
                           {"build", build_record(package.build)}}},
           {"properties", std::move(props)},
           {"passes", std::move(passes)},
           {"spirv_blobs", std::move(blobs)}};
  // Invalid UTF-8 in a string is replaced, never thrown on.
  return out.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

}  // namespace facet::package
