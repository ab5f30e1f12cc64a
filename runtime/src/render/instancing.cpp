#include "render/instancing.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>

namespace facet::runtime {
namespace {

bool has_instancing_on(const Draw& d) {
  return std::find(d.record.keywords.begin(), d.record.keywords.end(), "INSTANCING_ON") != d.record.keywords.end();
}

// The names a variant fills per instance: its instanced blocks' struct members.
std::vector<std::string> per_instance_names(const GpuProgram& program) {
  std::vector<std::string> names;
  for (const UniformBlock& block : program.blocks) {
    if (!is_instanced_block(block)) continue;
    for (const BlockMember& array : block.members) {
      for (const BlockMember& m : array.members) names.push_back(m.name);
    }
  }
  return names;
}

bool same_texture(const SceneTexture& a, const SceneTexture& b) {
  return a.name == b.name && a.builtin == b.builtin && a.srgb == b.srgb && a.alpha_from_gray == b.alpha_from_gray &&
         a.gltf_metallic_roughness == b.gltf_metallic_roughness && a.scale == b.scale && a.offset == b.offset;
}

// Equal materials but for the per-instance `names`.
bool same_material(const Material& a, const Material& b, const std::vector<std::string>& names) {
  auto shared = [&](const std::string& name) { return std::find(names.begin(), names.end(), name) == names.end(); };
  auto numbers_equal = [&](const Material& x, const Material& y) {
    for (const auto& [name, value] : x.numbers) {
      if (!shared(name)) continue;
      auto other = y.numbers.find(name);
      if (other == y.numbers.end() || other->second != value) return false;
    }
    return true;
  };
  if (!numbers_equal(a, b) || !numbers_equal(b, a) || a.textures.size() != b.textures.size()) return false;
  for (const auto& [name, texture] : a.textures) {
    auto other = b.textures.find(name);
    if (other == b.textures.end() || !same_texture(texture, other->second)) return false;
  }
  return true;
}

// What a run's first draw shares with the draws that may join it, worked
// out once per run.
struct Run {
  const GpuProgram* program = nullptr;
  std::vector<std::string> names;  // its per-instance names
  std::string state;               // describe() of its fixed-function state
};

bool can_join(const Draw& first, const Run& run, const Draw& d, const std::vector<ObjectState>& objects) {
  const ObjectState& a = objects[first.object];
  const ObjectState& b = objects[d.object];
  return has_instancing_on(d) && d.variant == first.variant && d.pass == first.pass && d.light == first.light &&
         d.grab_before.empty() && a.mesh == b.mesh && a.mirrored == b.mirrored && a.shader == b.shader &&
         !b.probes[0] && !b.probes[1] && !b.background && describe(d.state) == run.state &&
         same_material(a.material, b.material, run.names);
}

}  // namespace

bool is_instanced_block(const UniformBlock& block) { return block.name.starts_with("UnityInstancing_"); }

size_t merge_instanced_draws(std::vector<Draw>& draws, const std::vector<ObjectState>& objects) {
  std::vector<Draw> out;
  out.reserve(draws.size());
  size_t merged = 0;
  Run run;  // of out.back(), when it can start one
  bool open = false;
  for (Draw& d : draws) {
    if (open && std::max<size_t>(1, out.back().instances.size()) < kMaxInstances && can_join(out.back(), run, d, objects)) {
      Draw& first = out.back();
      if (first.instances.empty()) first.instances.push_back(first.object);
      first.instances.push_back(d.object);
      d.record.why += fmt::format("; instanced: drawn by draw of {} (GPU instancing)", first.record.object);
      first.instance_records.push_back(std::move(d.record));
      ++merged;
      continue;
    }
    const ObjectState& owner = objects[d.object];
    open = has_instancing_on(d) && !owner.probes[0] && !owner.probes[1] && !owner.background;
    if (open) {
      if (run.program != d.variant->program.get()) {
        run.program = d.variant->program.get();
        run.names = per_instance_names(*run.program);
      }
      run.state = describe(d.state);
    }
    out.push_back(std::move(d));
  }
  for (Draw& d : out) {
    if (d.instances.size() > 1) d.record.why += fmt::format("; instanced: {} objects in one draw", d.instances.size());
  }
  draws = std::move(out);
  return merged;
}

void fill_instanced_block(std::span<std::byte> out, const UniformBlock& block,
                          const std::vector<UniformLayers>& instances) {
  std::memset(out.data(), 0, out.size());
  for (const BlockMember& array : block.members) {
    const size_t count = array.array_dims.empty() ? 1 : array.array_dims[0];
    for (size_t i = 0; i < std::min(count, instances.size()); ++i) {
      const size_t element = array.offset + i * array.array_stride;
      if (element >= out.size()) break;
      for (const BlockMember& m : array.members) {
        const std::vector<float>* value = nullptr;
        const std::string built_in = m.name.ends_with("Array") ? m.name.substr(0, m.name.size() - 5) : "";
        for (const UniformValues* layer : instances[i]) {
          if (!layer) continue;
          if ((value = layer->find(m.name)) || (!built_in.empty() && (value = layer->find(built_in)))) break;
        }
        if (value) write_member(out.subspan(element), m, *value);
      }
    }
  }
}

}  // namespace facet::runtime
