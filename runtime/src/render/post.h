// The image-effect chain of a scene's "post" list, in the manner of Unity's
// OnRenderImage / Graphics.Blit(source, destination, material, pass): each
// step draws a full-screen quad with one pass of an effect shader into an
// RGBA16F image, with the previous image bound as _MainTex and the camera's
// depth as _CameraDepthTexture.
#pragma once

#include <memory>
#include <string_view>
#include <vector>

#include "render/draw_list.h"
#include "render/resources.h"
#include "render/failure.h"

namespace facet::runtime {

struct PostChain {
  std::vector<SceneObject> sources;  // the steps as objects, for messages ("post[1]")
  std::vector<ObjectState> steps;    // point into `sources`: the chain does not move
  DrawListResult list;               // one draw per step, in order
};

// Loads each effect's shader and material and compiles the variant of its
// pass; `quad` is the built-in quad on the GPU, `none` the black light.
Result<std::unique_ptr<PostChain>, Diagnostics> build_post_chain(const Context& context, const Scene& scene,
                                                                 ShaderLibrary& library, Resources& resources,
                                                                 GpuMesh* quad, const LightValues* none, int width,
                                                                 int height);

// The draw layer of a full-screen quad: the built-in quad's object matrix
// and a view-projection that takes it to the whole of clip space (the
// frame layer's other camera values stay the camera's).
UniformValues blit_uniforms();

// Whether the draw's program has a texture resource called `name`.
bool samples(const Draw& draw, std::string_view name);

}  // namespace facet::runtime
