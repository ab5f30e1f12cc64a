#include "spirv_fixup.h"

#include <spirv_cross/spirv.hpp>

#include <algorithm>
#include <cctype>
#include <map>
#include <set>
#include <unordered_map>

#include "facet/backend.h"

namespace facet::backend {
namespace {

constexpr size_t kHeaderWords = 5;

// One instruction: its words, opcode first.
using Instruction = std::vector<uint32_t>;

std::vector<Instruction> split(const std::vector<uint32_t>& spirv) {
  std::vector<Instruction> out;
  for (size_t i = kHeaderWords; i < spirv.size();) {
    uint32_t count = spirv[i] >> 16;
    if (count == 0 || i + count > spirv.size()) break;  // malformed: leave the rest alone
    out.emplace_back(spirv.begin() + i, spirv.begin() + i + count);
    i += count;
  }
  return out;
}

std::vector<uint32_t> join(const std::vector<uint32_t>& original, const std::vector<Instruction>& instructions) {
  std::vector<uint32_t> out(original.begin(), original.begin() + kHeaderWords);
  for (const Instruction& inst : instructions) out.insert(out.end(), inst.begin(), inst.end());
  return out;
}

spv::Op opcode(const Instruction& inst) { return spv::Op(inst[0] & 0xffff); }

std::string decode_string(const Instruction& inst, size_t first_word) {
  std::string out;
  for (size_t w = first_word; w < inst.size(); ++w) {
    for (int b = 0; b < 4; ++b) {
      char c = char((inst[w] >> (8 * b)) & 0xff);
      if (c == '\0') return out;
      out += c;
    }
  }
  return out;
}

Instruction make_name(uint32_t target, std::string_view name) {
  Instruction inst{0, target};
  size_t words = name.size() / 4 + 1;
  for (size_t w = 0; w < words; ++w) {
    uint32_t word = 0;
    for (size_t b = 0; b < 4; ++b) {
      size_t i = w * 4 + b;
      if (i < name.size()) word |= uint32_t(uint8_t(name[i])) << (8 * b);
    }
    inst.push_back(word);
  }
  inst[0] = (uint32_t(inst.size()) << 16) | spv::OpName;
  return inst;
}

// What the fix-ups need to know about the module.
struct ModuleIndex {
  std::unordered_map<uint32_t, std::string> names;
  std::unordered_map<uint32_t, std::string> semantics;
  std::unordered_map<uint32_t, uint32_t> sets;
  std::unordered_map<uint32_t, size_t> binding_inst, location_inst;  // id -> instruction index
  std::set<uint32_t> blocks;
  std::unordered_map<uint32_t, std::pair<uint32_t, spv::StorageClass>> variables;  // id -> pointer type, class
  std::vector<uint32_t> variable_order;
  std::unordered_map<uint32_t, uint32_t> pointees;
  std::unordered_map<uint32_t, Instruction> types;
  std::unordered_map<uint32_t, uint32_t> constants;
};

ModuleIndex index_module(const std::vector<Instruction>& insts) {
  ModuleIndex ix;
  for (size_t i = 0; i < insts.size(); ++i) {
    const Instruction& in = insts[i];
    switch (opcode(in)) {
      case spv::OpName: if (in.size() > 2) ix.names[in[1]] = decode_string(in, 2); break;
      case spv::OpDecorate:
        if (in.size() < 3) break;
        if (in[2] == spv::DecorationDescriptorSet && in.size() > 3) ix.sets[in[1]] = in[3];
        if (in[2] == spv::DecorationBinding && in.size() > 3) ix.binding_inst[in[1]] = i;
        if (in[2] == spv::DecorationLocation && in.size() > 3) ix.location_inst[in[1]] = i;
        if (in[2] == spv::DecorationBlock || in[2] == spv::DecorationBufferBlock) ix.blocks.insert(in[1]);
        break;
      case spv::OpDecorateString:
        if (in.size() > 3 && in[2] == spv::DecorationUserSemantic) ix.semantics[in[1]] = decode_string(in, 3);
        break;
      case spv::OpVariable:
        if (in.size() > 3) {
          ix.variables[in[2]] = {in[1], spv::StorageClass(in[3])};
          ix.variable_order.push_back(in[2]);
        }
        break;
      case spv::OpTypePointer: if (in.size() > 3) ix.pointees[in[1]] = in[3]; break;
      case spv::OpTypeArray: case spv::OpTypeMatrix: case spv::OpTypeVector: case spv::OpTypeStruct:
      case spv::OpTypeFloat: case spv::OpTypeInt: case spv::OpTypeBool:
        if (in.size() > 1) ix.types[in[1]] = in;
        break;
      case spv::OpConstant: if (in.size() > 3) ix.constants[in[2]] = in[3]; break;
      default: break;
    }
  }
  return ix;
}

// Locations a value of `type` occupies (32-bit types; enough for HLSL IO).
uint32_t location_count(const ModuleIndex& ix, uint32_t type, int depth = 0) {
  auto it = ix.types.find(type);
  if (it == ix.types.end() || depth > 16) return 1;
  const Instruction& t = it->second;
  switch (opcode(t)) {
    case spv::OpTypeArray: {
      auto length = ix.constants.find(t[3]);
      return (length == ix.constants.end() ? 1 : length->second) * location_count(ix, t[2], depth + 1);
    }
    case spv::OpTypeMatrix: return t[3];
    case spv::OpTypeStruct: {
      uint32_t sum = 0;
      for (size_t m = 2; m < t.size(); ++m) sum += location_count(ix, t[m], depth + 1);
      return sum;
    }
    default: return 1;
  }
}

std::string resource_key(const ModuleIndex& ix, uint32_t variable, uint32_t pointer_type) {
  auto pointee = ix.pointees.find(pointer_type);
  if (pointee != ix.pointees.end() && ix.blocks.count(pointee->second)) {
    auto name = ix.names.find(pointee->second);
    if (name != ix.names.end()) return name->second;
  }
  auto name = ix.names.find(variable);
  return name == ix.names.end() ? std::string() : name->second;
}

void assign_material_bindings(std::vector<Instruction>& insts, const ModuleIndex& ix,
                              const std::vector<DeclaredResource>& declared) {
  auto table = material_bindings(declared);
  std::map<std::string, uint32_t> by_key(table.begin(), table.end());
  uint32_t next_free = 0;
  for (const auto& [key, binding] : table) next_free = std::max(next_free, binding + 1);
  for (uint32_t var : ix.variable_order) {
    auto set = ix.sets.find(var);
    auto binding = ix.binding_inst.find(var);
    if (set == ix.sets.end() || set->second != kMaterialSet || binding == ix.binding_inst.end()) continue;
    std::string key = resource_key(ix, var, ix.variables.at(var).first);
    auto found = by_key.find(key == kGlobalsBlock ? std::string("$Global") : key);
    insts[binding->second][3] = found != by_key.end() ? found->second : next_free++;
  }
}

struct Interface {
  uint32_t id;
  std::string semantic;
  uint32_t count;
};

// Rewrites the locations of one storage class; false when they would overlap.
bool assign_locations(std::vector<Instruction>& insts, const ModuleIndex& ix, const std::vector<Interface>& vars,
                      Stage stage, bool input, std::vector<std::string>& overlaps) {
  // Semantics without a fixed slot follow the fixed ones, alphabetically.
  uint32_t next_other = stage == Stage::vertex && input ? 16 : stage == Stage::fragment && !input ? 8 : 23;
  std::map<std::string, uint32_t> other_sizes, others;  // semantic -> locations used / first location
  for (const Interface& v : vars) {
    if (!semantic_location(v.semantic, stage, input)) {
      other_sizes[v.semantic] = std::max(other_sizes[v.semantic], v.count);
    }
  }
  for (const auto& [semantic, size] : other_sizes) {
    others[semantic] = next_other;
    next_other += size;
  }
  std::vector<std::pair<uint32_t, uint32_t>> taken;  // [begin, end)
  std::vector<std::pair<size_t, uint32_t>> edits;
  for (const Interface& v : vars) {
    std::optional<uint32_t> loc = semantic_location(v.semantic, stage, input);
    if (!loc) loc = others.at(v.semantic);
    for (const auto& [b, e] : taken) {
      if (*loc < e && b < *loc + v.count) {
        overlaps.push_back(v.semantic);
        return false;
      }
    }
    taken.emplace_back(*loc, *loc + v.count);
    edits.emplace_back(ix.location_inst.at(v.id), *loc);
  }
  for (const auto& [inst, loc] : edits) insts[inst][3] = loc;
  return true;
}

void assign_semantic_locations(std::vector<Instruction>& insts, const ModuleIndex& ix, Stage stage,
                               FixupReport& report) {
  std::vector<Interface> inputs, outputs;
  for (uint32_t var : ix.variable_order) {
    auto [pointer, storage] = ix.variables.at(var);
    if (storage != spv::StorageClassInput && storage != spv::StorageClassOutput) continue;
    if (!ix.location_inst.count(var)) continue;  // built-ins
    auto semantic = ix.semantics.find(var);
    if (semantic == ix.semantics.end()) return;  // no semantics: keep glslang's numbering
    auto pointee = ix.pointees.find(pointer);
    uint32_t type = pointee == ix.pointees.end() ? 0 : pointee->second;
    // Geometry inputs, hull inputs/outputs and domain inputs are arrays with
    // one element per vertex; each element uses the same locations.
    bool input = storage == spv::StorageClassInput;
    bool per_vertex = (stage == Stage::geometry && input) || stage == Stage::hull || (stage == Stage::domain && input);
    auto array = ix.types.find(type);
    if (per_vertex && array != ix.types.end() && opcode(array->second) == spv::OpTypeArray) type = array->second[2];
    Interface v{var, semantic->second, type == 0 ? 1 : location_count(ix, type)};
    (storage == spv::StorageClassInput ? inputs : outputs).push_back(std::move(v));
  }
  assign_locations(insts, ix, inputs, stage, true, report.overlapping_semantics);
  assign_locations(insts, ix, outputs, stage, false, report.overlapping_semantics);
}

std::pair<std::string, uint32_t> split_semantic(std::string_view semantic) {
  std::string upper(semantic);
  std::transform(upper.begin(), upper.end(), upper.begin(), [](unsigned char c) { return char(std::toupper(c)); });
  size_t digits = upper.size();
  while (digits > 0 && std::isdigit(static_cast<unsigned char>(upper[digits - 1]))) --digits;
  uint32_t index = digits < upper.size() && upper.size() - digits < 4 ? uint32_t(std::stoul(upper.substr(digits))) : 0;
  return {upper.substr(0, digits), index};
}

}  // namespace

std::optional<uint32_t> semantic_location(std::string_view semantic, Stage stage, bool input) {
  auto [base, index] = split_semantic(semantic);
  if (stage == Stage::vertex && input) {
    if (base == "TEXCOORD" && index < 8) return 4 + index;
    static const std::map<std::pair<std::string, uint32_t>, uint32_t> table = {
        {{"POSITION", 0}, 0}, {{"SV_POSITION", 0}, 0}, {{"NORMAL", 0}, 1},        {{"TANGENT", 0}, 2},
        {{"COLOR", 0}, 3},    {{"BLENDWEIGHT", 0}, 12}, {{"BLENDWEIGHTS", 0}, 12}, {{"BLENDINDICES", 0}, 13},
        {{"COLOR", 1}, 14},   {{"BINORMAL", 0}, 15}};
    auto it = table.find({base, index});
    return it == table.end() ? std::nullopt : std::optional<uint32_t>(it->second);
  }
  if (stage == Stage::fragment && !input) {
    if ((base == "SV_TARGET" || base == "COLOR") && index < 8) return index;
    return std::nullopt;
  }
  if (base == "TEXCOORD" && index < 16) return index;
  static const std::map<std::pair<std::string, uint32_t>, uint32_t> varyings = {
      {{"COLOR", 0}, 16},   {{"COLOR", 1}, 17},    {{"NORMAL", 0}, 18}, {{"TANGENT", 0}, 19},
      {{"BINORMAL", 0}, 20}, {{"POSITION", 0}, 21}, {{"FOG", 0}, 22}};
  auto it = varyings.find({base, index});
  return it == varyings.end() ? std::nullopt : std::optional<uint32_t>(it->second);
}

std::vector<std::pair<std::string, uint32_t>> material_bindings(const std::vector<DeclaredResource>& declared) {
  auto in_material = [](const DeclaredResource& r) { return !r.has_set || r.set == kMaterialSet; };
  std::set<uint32_t> taken;
  for (const DeclaredResource& r : declared) {
    if (in_material(r) && r.has_binding) taken.insert(r.binding);
  }
  std::vector<std::pair<std::string, uint32_t>> out;
  uint32_t next = 0;
  auto take_next = [&] {
    while (taken.count(next)) ++next;
    taken.insert(next);
    return next;
  };
  for (const DeclaredResource& r : declared) {
    bool globals = r.block && (r.key == "$Global" || r.key == kGlobalsBlock);
    if (globals && in_material(r)) out.emplace_back("$Global", r.has_binding ? r.binding : take_next());
  }
  for (const DeclaredResource& r : declared) {
    bool globals = r.block && (r.key == "$Global" || r.key == kGlobalsBlock);
    if (!in_material(r) || globals) continue;
    out.emplace_back(r.key, r.has_binding ? r.binding : take_next());
  }
  return out;
}

// glslang leaves an Input or Output variable of an empty struct (an HLSL
// stage input with no members) out of the entry point's interface, which
// SPIR-V requires it to be in, and without the Location Vulkan requires;
// every Input/Output variable is listed, and an empty struct one gets
// Location 0 (it occupies no location).
void list_interface_variables(std::vector<Instruction>& insts, const ModuleIndex& ix) {
  std::vector<Instruction> locations;
  for (uint32_t id : ix.variable_order) {
    auto [pointer, sc] = ix.variables.at(id);
    if ((sc != spv::StorageClassInput && sc != spv::StorageClassOutput) || ix.location_inst.count(id)) continue;
    auto pointee = ix.pointees.find(pointer);
    auto type = pointee == ix.pointees.end() ? ix.types.end() : ix.types.find(pointee->second);
    // A geometry or tessellation stage's input is an array of them.
    while (type != ix.types.end() && opcode(type->second) == spv::OpTypeArray && type->second.size() > 2) {
      type = ix.types.find(type->second[2]);
    }
    if (type == ix.types.end() || opcode(type->second) != spv::OpTypeStruct || type->second.size() != 2) continue;
    locations.push_back({(4u << 16) | spv::OpDecorate, id, uint32_t(spv::DecorationLocation), 0u});
  }
  if (!locations.empty()) {
    auto first = std::find_if(insts.begin(), insts.end(), [](const Instruction& i) { return opcode(i) == spv::OpDecorate; });
    insts.insert(first, locations.begin(), locations.end());
  }
  for (Instruction& inst : insts) {
    if (opcode(inst) != spv::OpEntryPoint || inst.size() < 4) continue;
    size_t first = 3 + (decode_string(inst, 3).size() + 4) / 4;  // after the name's words
    std::set<uint32_t> listed(inst.begin() + long(std::min(first, inst.size())), inst.end());
    for (uint32_t id : ix.variable_order) {
      spv::StorageClass sc = ix.variables.at(id).second;
      if ((sc == spv::StorageClassInput || sc == spv::StorageClassOutput) && !listed.count(id)) inst.push_back(id);
    }
    inst[0] = (uint32_t(inst.size()) << 16) | spv::OpEntryPoint;
  }
}

FixupReport fix_up_spirv(std::vector<uint32_t>& spirv, const std::vector<DeclaredResource>& declared, Stage stage,
                         bool hlsl) {
  FixupReport report;
  if (spirv.size() < kHeaderWords) return report;
  std::vector<Instruction> insts = split(spirv);
  ModuleIndex ix = index_module(insts);
  for (Instruction& inst : insts) {
    if (opcode(inst) == spv::OpName && inst.size() > 2 && decode_string(inst, 2) == "$Global") {
      inst = make_name(inst[1], kGlobalsBlock);
    }
  }
  assign_material_bindings(insts, ix, declared);
  if (hlsl) assign_semantic_locations(insts, ix, stage, report);
  list_interface_variables(insts, ix);
  spirv = join(spirv, insts);
  return report;
}

}  // namespace facet::backend
