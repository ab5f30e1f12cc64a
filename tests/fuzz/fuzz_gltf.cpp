// Arbitrary bytes as a glTF file through the runtime's glTF loader, with
// its materials (load_gltf reads files only: each input is written over one
// file in the target's temporary folder, as .glb when it starts with the
// GLB magic "glTF", else as .gltf), then tangents and bounds of what loads.
#include "facet/runtime/gltf.h"
#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::string gltf = facet::fuzz::TempDir::get().file("mesh.gltf");
  static const std::string glb = facet::fuzz::TempDir::get().file("mesh.glb");
  bool binary = size >= 4 && data[0] == 'g' && data[1] == 'l' && data[2] == 'T' && data[3] == 'F';
  const std::string& path = binary ? glb : gltf;
  facet::fuzz::write_bytes(path, facet::fuzz::as_text(data, size));
  facet::Diagnostics error;
  std::optional<facet::runtime::GltfModel> model =
      facet::runtime::load_gltf(path, error, {.materials = true, .limits = {}});
  if (model) {
    facet::runtime::MeshData mesh = facet::runtime::merge_gltf_parts(*model);
    facet::runtime::compute_tangents(mesh);
    (void)facet::runtime::mesh_bounds(mesh);
  }
  return 0;
}
