#include "facet/reflection_json.h"

#include <nlohmann/json.hpp>

#include <array>
#include <exception>

namespace facet {
namespace {

using nlohmann::json;
using ordered = nlohmann::ordered_json;

constexpr std::array<std::pair<ResourceKind, std::string_view>, 6> kKinds = {{
    {ResourceKind::combined_image_sampler, "combined_image_sampler"},
    {ResourceKind::separate_image, "separate_image"},
    {ResourceKind::separate_sampler, "separate_sampler"},
    {ResourceKind::storage_image, "storage_image"},
    {ResourceKind::storage_buffer, "storage_buffer"},
    {ResourceKind::uniform_texel_buffer, "uniform_texel_buffer"},
}};

ResourceKind parse_kind(const std::string& name) {
  for (const auto& [kind, text] : kKinds) {
    if (text == name) return kind;
  }
  throw json::other_error::create(501, "unknown resource kind '" + name + "'", nullptr);
}

ordered variable_json(const StageVariable& v) {
  return {{"name", v.name}, {"semantic", v.semantic}, {"location", v.location}, {"type", v.type},
          {"array_size", v.array_size}};
}

StageVariable variable_from(const json& j) {
  return {j.at("name").get<std::string>(), j.at("semantic").get<std::string>(), j.at("location").get<uint32_t>(),
          j.at("type").get<std::string>(), j.at("array_size").get<uint32_t>()};
}

ordered member_json(const BlockMember& m) {
  ordered members = ordered::array();
  for (const BlockMember& child : m.members) members.push_back(member_json(child));
  return {{"name", m.name},
          {"type", m.type},
          {"offset", m.offset},
          {"size", m.size},
          {"array_dims", m.array_dims},
          {"array_stride", m.array_stride},
          {"matrix_stride", m.matrix_stride},
          {"row_major", m.row_major},
          {"members", std::move(members)}};
}

BlockMember member_from(const json& j, int depth = 0) {
  if (depth > 64) throw json::other_error::create(502, "members nested too deeply", nullptr);
  BlockMember m;
  m.name = j.at("name").get<std::string>();
  m.type = j.at("type").get<std::string>();
  m.offset = j.at("offset").get<uint32_t>();
  m.size = j.at("size").get<uint32_t>();
  m.array_dims = j.at("array_dims").get<std::vector<uint32_t>>();
  m.array_stride = j.at("array_stride").get<uint32_t>();
  m.matrix_stride = j.at("matrix_stride").get<uint32_t>();
  m.row_major = j.at("row_major").get<bool>();
  for (const json& child : j.at("members")) m.members.push_back(member_from(child, depth + 1));
  return m;
}

ordered block_json(const UniformBlock& b) {
  ordered members = ordered::array();
  for (const BlockMember& m : b.members) members.push_back(member_json(m));
  return {{"name", b.name}, {"set", b.set}, {"binding", b.binding}, {"size", b.size},
          {"push_constant", b.push_constant}, {"members", std::move(members)}};
}

UniformBlock block_from(const json& j) {
  UniformBlock b;
  b.name = j.at("name").get<std::string>();
  b.set = j.at("set").get<uint32_t>();
  b.binding = j.at("binding").get<uint32_t>();
  b.size = j.at("size").get<uint32_t>();
  b.push_constant = j.at("push_constant").get<bool>();
  for (const json& m : j.at("members")) b.members.push_back(member_from(m));
  return b;
}

ordered resource_json(const ResourceBinding& r) {
  return {{"name", r.name}, {"kind", resource_kind_name(r.kind)}, {"dim", r.dim}, {"arrayed", r.arrayed},
          {"set", r.set},   {"binding", r.binding},                {"array_size", r.array_size}};
}

ResourceBinding resource_from(const json& j) {
  ResourceBinding r;
  r.name = j.at("name").get<std::string>();
  r.kind = parse_kind(j.at("kind").get<std::string>());
  r.dim = j.at("dim").get<std::string>();
  r.arrayed = j.at("arrayed").get<bool>();
  r.set = j.at("set").get<uint32_t>();
  r.binding = j.at("binding").get<uint32_t>();
  r.array_size = j.at("array_size").get<uint32_t>();
  return r;
}

template <typename T, typename F>
ordered array_of(const std::vector<T>& items, F&& to) {
  ordered out = ordered::array();
  for (const T& item : items) out.push_back(to(item));
  return out;
}

template <typename T, typename F>
std::vector<T> vector_of(const json& j, F&& from) {
  if (!j.is_array()) throw json::type_error::create(302, "expected an array", nullptr);
  std::vector<T> out;
  for (const json& item : j) out.push_back(from(item));
  return out;
}

}  // namespace

std::string_view resource_kind_name(ResourceKind kind) {
  for (const auto& [k, text] : kKinds) {
    if (k == kind) return text;
  }
  return "unknown";
}

nlohmann::ordered_json reflection_to_ordered_json(const StageReflection& r) {
  ordered j = ordered::object();
  j["stage"] = std::string(stage_name(r.stage));
  j["entry_point"] = r.entry_point;
  j["inputs"] = array_of(r.inputs, variable_json);
  j["outputs"] = array_of(r.outputs, variable_json);
  j["uniform_blocks"] = array_of(r.uniform_blocks, block_json);
  j["resources"] = array_of(r.resources, resource_json);
  j["spec_constants"] = array_of(r.spec_constants, [](const SpecConstant& s) {
    return ordered{{"name", s.name}, {"id", s.id}, {"type", s.type}, {"default_value", s.default_value}};
  });
  j["property_bindings"] = array_of(r.property_bindings, [](const PropertyBinding& p) {
    return ordered{{"property", p.property}, {"role", p.role}, {"block", p.block}, {"member", p.member}};
  });
  return j;
}

// nlohmann::json keeps its keys sorted: the same reflection, the same bytes.
void to_json(nlohmann::json& j, const StageReflection& r) { j = nlohmann::json(reflection_to_ordered_json(r)); }

void from_json(const nlohmann::json& j, StageReflection& r) {
  auto stage = parse_stage(j.at("stage").get<std::string>());
  if (!stage) throw json::other_error::create(501, "unknown stage", &j);
  r.stage = *stage;
  r.entry_point = j.at("entry_point").get<std::string>();
  r.inputs = vector_of<StageVariable>(j.at("inputs"), variable_from);
  r.outputs = vector_of<StageVariable>(j.at("outputs"), variable_from);
  r.uniform_blocks = vector_of<UniformBlock>(j.at("uniform_blocks"), block_from);
  r.resources = vector_of<ResourceBinding>(j.at("resources"), resource_from);
  r.spec_constants = vector_of<SpecConstant>(j.at("spec_constants"), [](const json& s) {
    return SpecConstant{s.at("name").get<std::string>(), s.at("id").get<uint32_t>(), s.at("type").get<std::string>(),
                        s.at("default_value").get<std::string>()};
  });
  r.property_bindings = vector_of<PropertyBinding>(j.at("property_bindings"), [](const json& p) {
    return PropertyBinding{p.at("property").get<std::string>(), p.at("role").get<std::string>(),
                           p.at("block").get<std::string>(), p.at("member").get<std::string>()};
  });
}

Result<StageReflection> reflection_from_json(const nlohmann::json& j) {
  // nlohmann throws; this is the boundary.
  try {
    StageReflection r;
    from_json(j, r);
    return r;
  } catch (const std::exception& e) {
    return failure(std::string("invalid reflection JSON: ") + e.what());
  }
}

std::string reflection_to_json_text(const StageReflection& reflection, int indent) {
  json j = reflection;
  return j.dump(indent);
}

Result<StageReflection> reflection_from_json_text(const std::string& text) {
  json j = json::parse(text, nullptr, false);
  if (j.is_discarded()) return failure("invalid reflection JSON: not JSON");
  return reflection_from_json(j);
}

}  // namespace facet
