#include "render/capture.h"

#include <cstring>

namespace facet::runtime {

size_t CaptureBuilder::program(const GpuProgram& program) {
  if (auto it = programs_.find(&program); it != programs_.end()) return it->second;
  CapturedProgram p;
  for (size_t i = 0; i < program.modules.size(); ++i) {
    p.stages.push_back({program.stages[i], program.entries[i], program.spirv[i]});
  }
  p.attributes = vertex_attributes(program);
  for (size_t s = 0; s < p.sets.size(); ++s) p.sets[s] = program.set_bindings[s];
  p.push_constant_bytes = program.push_constant_bytes;
  p.push_stages = program.push_stages;
  capture_.programs.push_back(std::move(p));
  return programs_[&program] = capture_.programs.size() - 1;
}

size_t CaptureBuilder::mesh(const GpuMesh& mesh) {
  if (auto it = meshes_.find(&mesh); it != meshes_.end()) return it->second;
  CapturedMesh m;
  // Mesh buffers stay mapped: their bytes are what the draws read.
  const auto* vertices = static_cast<const std::byte*>(mesh.vertices.data());
  m.vertices.assign(vertices, vertices + mesh.vertices.size());
  m.indices.resize(mesh.index_count);
  std::memcpy(m.indices.data(), mesh.indices.data(), size_t(mesh.index_count) * 4);
  capture_.meshes.push_back(std::move(m));
  return meshes_[&mesh] = capture_.meshes.size() - 1;
}

Result<int, std::string> CaptureBuilder::image(const Image* image) {
  if (auto it = images_.find(image); it != images_.end()) return it->second;
  const std::vector<std::vector<std::byte>>* mips = resources_.pixels_of(image);
  if (!mips) return unexpected(std::string("a frame capture cannot include an image made without its texels"));
  CapturedImage c{image->desc(), *mips};
  c.desc.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  capture_.images.push_back(std::move(c));
  return images_[image] = int(capture_.images.size() - 1);
}

}  // namespace facet::runtime
