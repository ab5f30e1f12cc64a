// The baseline of the frame-overhead benchmark: a hand-written Vulkan loop
// that draws a FrameCapture (the same meshes, SPIR-V, fixed-function state,
// uniform bytes and texels facet used) with everything prepared up front:
// one pipeline per distinct program and state, descriptor sets written once, uniform buffers
// filled once, one command buffer and fence reused. A frame is then only
// recording, submitting and waiting, which is the least any renderer does.
// Buffers and images are allocated through facet's small helpers; that is
// setup, outside the timed frames.
#pragma once

#include <vulkan/vulkan.h>

#include <memory>
#include <string>
#include <vector>

#include "facet/result.h"
#include "facet/runtime/frame_capture.h"

namespace facet::runtime {
class Context;
}

namespace facet::bench {

struct BareFrame {
  double host_ms = 0;  // recording to the fence
  double cpu_ms = 0;   // recording and submission: the host's work, without the wait
  double gpu_ms = 0;   // from timestamps; 0 without them
};

struct BareState;  // the Vulkan objects, in bare_renderer.cpp

class BareRenderer {
 public:
  BareRenderer(runtime::Context& context, const runtime::FrameCapture& capture);
  ~BareRenderer();
  BareRenderer(const BareRenderer&) = delete;
  BareRenderer& operator=(const BareRenderer&) = delete;

  // Creates every object; an error names what failed.
  Result<void, std::string> prepare();
  Result<BareFrame, std::string> render_frame();
  // The last frame's colour target, RGBA half floats, row 0 at the top.
  std::vector<uint16_t> pixels() const;

 private:
  std::unique_ptr<BareState> state_;
};

}  // namespace facet::bench
