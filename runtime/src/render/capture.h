// Filling a FrameCapture while render_scene records its first frame: each
// program, mesh and image goes in once, draws refer to them by index.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "facet/result.h"
#include "facet/runtime/frame_capture.h"
#include "render/draw_list.h"
#include "render/program.h"
#include "render/resources.h"

namespace facet::runtime {

class CaptureBuilder {
 public:
  CaptureBuilder(FrameCapture& capture, const Resources& resources) : capture_(capture), resources_(resources) {}

  size_t program(const GpuProgram& program);
  size_t mesh(const GpuMesh& mesh);
  // The image's index; an error when its texels were not kept.
  Result<int, std::string> image(const Image* image);

 private:
  FrameCapture& capture_;
  const Resources& resources_;
  std::map<const GpuProgram*, size_t> programs_;
  std::map<const GpuMesh*, size_t> meshes_;
  std::map<const Image*, int> images_;
};

}  // namespace facet::runtime
