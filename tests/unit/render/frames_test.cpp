// Repeated frames (RenderOptions::frames) and frame captures: later frames
// draw the same image from the kept descriptor sets, and a capture holds
// everything a bare Vulkan loop needs to draw the very same pixels.
#include <gtest/gtest.h>

#include <glm/gtc/packing.hpp>
#include <set>

#include "frame_overhead/bare_renderer.h"
#include "facet/runtime/frame_capture.h"
#include "facet/runtime/scene.h"
#include "render_test_support.h"

namespace facet::runtime {
namespace {

class FramesTest : public test_support::LavapipeTest {
 protected:
  static Scene example(const std::string& name) {
    auto scene = load_scene(std::string(FACET_SOURCE_DIR) + "/examples/scenes/" + name);
    EXPECT_TRUE(scene) << scene.error().message;
    return scene ? *scene : Scene{};
  }
  static RenderedFrame render(const Scene& scene, RenderOptions options) {
    options.width = 48;
    options.height = 36;
    auto frame = render_scene(context(), scene, test_support::with_compiler(options));
    EXPECT_TRUE(frame) << frame.error().message;
    return frame ? std::move(*frame) : RenderedFrame{};
  }
};

TEST_F(FramesTest, LaterFramesDrawTheSameImageAsTheFirst) {
  Scene scene = example("phong_lights.json");
  RenderedFrame one = render(scene, {});
  RenderedFrame three = render(scene, {.frames = 3});
  EXPECT_EQ(one.hdr, three.hdr);
  EXPECT_EQ(three.stats.frame_ms.size(), 3u);
  EXPECT_EQ(three.stats.frame_gpu_ms.size(), 3u);
  EXPECT_EQ(one.stats.triangles, three.stats.triangles);
  EXPECT_EQ(one.stats.draws, three.stats.draws);
}

TEST_F(FramesTest, AfterFrameIsCalledOncePerFrameInOrder) {
  std::vector<int> seen;
  render(example("unlit.json"), {.frames = 4, .after_frame = [&](int f) { seen.push_back(f); }});
  EXPECT_EQ(seen, (std::vector<int>{0, 1, 2, 3}));
}

TEST_F(FramesTest, ZeroFramesIsAnError) {
  auto frame = render_scene(context(), example("unlit.json"), test_support::with_compiler({.frames = 0}));
  ASSERT_FALSE(frame);
  EXPECT_NE(frame.error().message.find("frames"), std::string::npos);
}

TEST_F(FramesTest, CaptureHoldsEveryDrawWithItsUniformBytesAndTextures) {
  FrameCapture capture;
  RenderedFrame frame = render(example("textured.json"), {.capture = &capture});
  ASSERT_EQ(capture.draws.size(), frame.stats.draws);
  EXPECT_EQ(capture.width, 48u);
  std::set<size_t> programs;
  for (const CapturedDraw& d : capture.draws) {
    programs.insert(d.program);
    size_t uniforms = 0;
    for (const CapturedDescriptor& desc : d.descriptors) {
      if (desc.type == VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER) {
        ++uniforms;
        EXPECT_FALSE(desc.uniform_bytes.empty());
      } else if (desc.type != VK_DESCRIPTOR_TYPE_SAMPLER) {
        ASSERT_GE(desc.image, 0);
        EXPECT_LT(size_t(desc.image), capture.images.size());
      }
    }
    EXPECT_GT(uniforms, 0u);
    ASSERT_LT(d.program, capture.programs.size());
    EXPECT_GE(capture.programs[d.program].stages.size(), 2u);
  }
  EXPECT_EQ(programs.size(), capture.programs.size());
  // The checker texture file: its full mip chain is in the capture.
  bool has_mips = false;
  for (const CapturedImage& image : capture.images) has_mips |= image.desc.mips > 1 && image.mips.size() == image.desc.mips;
  EXPECT_TRUE(has_mips);
}

TEST_F(FramesTest, ABareVulkanLoopDrawsTheCaptureToTheSamePixels) {
  for (const char* name : {"phong_lights.json", "textured.json", "transparency.json", "sky_ambient.json"}) {
    SCOPED_TRACE(name);
    Scene scene = example(name);
    FrameCapture capture;
    RenderedFrame frame = render(scene, {.capture = &capture});
    bench::BareRenderer bare(context(), capture);
    auto prepared = bare.prepare();
    ASSERT_TRUE(prepared) << prepared.error();
    auto drawn = bare.render_frame();
    ASSERT_TRUE(drawn) << drawn.error();
    std::vector<uint16_t> pixels = bare.pixels();
    ASSERT_EQ(pixels.size(), frame.hdr.size());
    size_t different = 0;
    for (size_t i = 0; i < pixels.size(); ++i) {
      float value = glm::unpackHalf1x16(pixels[i]) * (i % 4 == 3 ? 1.0f : scene.camera.exposure);
      different += value != frame.hdr[i];
    }
    EXPECT_EQ(different, 0u);
  }
}

TEST_F(FramesTest, ACaptureOfImageEffectsIsRefused) {
  FrameCapture capture;
  auto frame = render_scene(context(), example("post_chain.json"), test_support::with_compiler({.capture = &capture}));
  ASSERT_FALSE(frame);
  EXPECT_NE(frame.error().message.find("image effects"), std::string::npos);
}

}  // namespace
}  // namespace facet::runtime
