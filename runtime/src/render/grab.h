// GrabPass: the screen copied into a texture between two draws, as Unity
// does it: `GrabPass { }` before every object that has one (into
// _GrabTexture), `GrabPass { "_Name" }` once a frame, the first time an
// object with it is drawn. The scene's render pass is split at each grab.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "facet/runtime/image.h"
#include "facet/runtime/renderer.h"
#include "facet/runtime/vulkan_context.h"
#include "render/draw_list.h"
#include "render/failure.h"

namespace facet::runtime {

struct GrabPoint {
  size_t draw = 0;                 // the screen is copied right before this draw
  std::vector<std::string> names;  // into these textures
};

struct GrabPlan {
  std::vector<GrabPoint> points;         // in draw order
  std::map<std::string, Image> images;   // every grab texture, by name
};

// Where the screen is copied in `draws` (submission order) and the images
// it is copied into. A draw that samples a grab texture no GrabPass filled
// before it is an error: Unity would sample an unset texture.
Result<GrabPlan, Diagnostics> plan_grabs(const Context& context, const Scene& scene, const std::vector<Draw>& draws,
                                         uint32_t width, uint32_t height);

// Copies `color` (TRANSFER_SRC_OPTIMAL, as a part of the split render pass
// leaves it) into the point's images and hands it back to the next part in
// COLOR_ATTACHMENT_OPTIMAL; the depth attachment's writes are made visible
// to the next part's depth tests. `grabbed` tracks which images already hold
// a grab in this command buffer (their layout is then SHADER_READ_ONLY).
void record_grab(VkCommandBuffer commands, const Image& color, const GrabPoint& point, GrabPlan& plan,
                 std::map<std::string, bool>& grabbed);

}  // namespace facet::runtime
