// Arbitrary bytes as an OBJ file through the runtime's mesh loader
// (load_obj reads files only: each input is written over one file in the
// target's temporary folder), then tangents and bounds of what loads.
#include "facet/runtime/mesh.h"
#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::string path = facet::fuzz::TempDir::get().file("mesh.obj");
  facet::fuzz::write_bytes(path, facet::fuzz::as_text(data, size));
  facet::Diagnostics error;
  std::optional<facet::runtime::MeshData> mesh = facet::runtime::load_obj(path, error);
  if (mesh) {
    facet::runtime::compute_tangents(*mesh);
    (void)facet::runtime::mesh_bounds(*mesh);
  }
  return 0;
}
