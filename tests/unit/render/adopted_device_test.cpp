// adopt_context: facet draws on an engine's own instance, device and queue,
// the same pixels as on a device of its own, and leaves them to the engine.
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include <glm/gtc/packing.hpp>

#include "facet/runtime/image.h"
#include "facet/runtime/renderer.h"
#include "facet/runtime/scene.h"
#include "facet/runtime/vulkan_context.h"
#include "render_test_support.h"

namespace facet::runtime {
namespace {

// What an engine creates by itself: an instance with the validation layer
// and debug utils, lavapipe, a device with one graphics queue and the
// features it chose. Destroyed by the engine, after facet's context.
struct EngineDevice {
  VkInstance instance = VK_NULL_HANDLE;
  VkPhysicalDevice physical = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  VkQueue queue = VK_NULL_HANDLE;
  uint32_t family = 0;
  VkPhysicalDeviceFeatures features{};

  EngineDevice() {
    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.apiVersion = VK_API_VERSION_1_2;
    const char* layer = "VK_LAYER_KHRONOS_validation";
    const char* extension = VK_EXT_DEBUG_UTILS_EXTENSION_NAME;
    VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    info.pApplicationInfo = &app;
    info.enabledLayerCount = 1;
    info.ppEnabledLayerNames = &layer;
    info.enabledExtensionCount = 1;
    info.ppEnabledExtensionNames = &extension;
    if (vkCreateInstance(&info, nullptr, &instance) != VK_SUCCESS) return;
    uint32_t count = 0;
    vkEnumeratePhysicalDevices(instance, &count, nullptr);
    std::vector<VkPhysicalDevice> devices(count);
    vkEnumeratePhysicalDevices(instance, &count, devices.data());
    for (VkPhysicalDevice d : devices) {
      VkPhysicalDeviceProperties p{};
      vkGetPhysicalDeviceProperties(d, &p);
      if (p.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU) physical = d;
    }
    if (!physical) return;
    uint32_t families = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &families, nullptr);
    std::vector<VkQueueFamilyProperties> props(families);
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &families, props.data());
    for (uint32_t i = 0; i < families; ++i) {
      if (props[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) {
        family = i;
        break;
      }
    }
    VkPhysicalDeviceFeatures supported{};
    vkGetPhysicalDeviceFeatures(physical, &supported);
    features.independentBlend = supported.independentBlend;
    features.depthClamp = supported.depthClamp;
    float priority = 1;
    VkDeviceQueueCreateInfo queue_info{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queue_info.queueFamilyIndex = family;
    queue_info.queueCount = 1;
    queue_info.pQueuePriorities = &priority;
    VkDeviceCreateInfo device_info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    device_info.queueCreateInfoCount = 1;
    device_info.pQueueCreateInfos = &queue_info;
    device_info.pEnabledFeatures = &features;
    if (vkCreateDevice(physical, &device_info, nullptr, &device) != VK_SUCCESS) return;
    vkGetDeviceQueue(device, family, 0, &queue);
  }
  ~EngineDevice() {
    if (device) vkDestroyDevice(device, nullptr);
    if (instance) vkDestroyInstance(instance, nullptr);
  }
  AdoptedDevice adopted() const {
    return {.instance = instance, .physical_device = physical, .device = device, .queue = queue,
            .queue_family = family, .enabled_features = features, .record_messages = true};
  }
};

class AdoptedDeviceTest : public test_support::LavapipeTest {};

TEST_F(AdoptedDeviceTest, DrawsTheSamePixelsOnTheEnginesDeviceAndLeavesItToTheEngine) {
  EngineDevice engine;
  ASSERT_TRUE(engine.queue) << "no lavapipe device with a graphics queue";
  Scene scene = test_support::example_scene("phong_lights.json");
  RenderedFrame own = *render_scene(context(), scene, test_support::with_compiler({}));
  {
    auto adopted = adopt_context(engine.adopted());
    ASSERT_TRUE(adopted) << describe(adopted.error());
    EXPECT_EQ((*adopted)->device(), engine.device);
    EXPECT_EQ((*adopted)->device_info().name, context().device_info().name);
    auto renderer = test_support::create_renderer(**adopted, {.shader_compiler = test_support::with_compiler({}).shader_compiler});
    ASSERT_TRUE(renderer) << renderer.error().message;
    RenderedFrame frame;
    for (int f = 0; f < 3; ++f) {
      scene.time = float(f);
      ASSERT_TRUE(test_support::render(**renderer, scene, frame)) << "frame " << f;
    }
    EXPECT_EQ(frame.stats.frame_path, FramePath::repeated);
    scene.time = 0;
    ASSERT_TRUE(test_support::render(**renderer, scene, frame));
    EXPECT_EQ(frame.hdr, own.hdr);
    renderer->reset();
    EXPECT_TRUE((*adopted)->messages().empty()) << (*adopted)->messages_text();
  }
  // The engine's device outlives facet's context and still works.
  EXPECT_EQ(vkDeviceWaitIdle(engine.device), VK_SUCCESS);
  VkFenceCreateInfo fence_info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  VkFence fence = VK_NULL_HANDLE;
  EXPECT_EQ(vkCreateFence(engine.device, &fence_info, nullptr, &fence), VK_SUCCESS);
  vkDestroyFence(engine.device, fence, nullptr);
}

TEST_F(AdoptedDeviceTest, MissingHandlesAndAQueueWithoutGraphicsAreErrors) {
  auto none = adopt_context({});
  ASSERT_FALSE(none);
  EXPECT_NE(describe(none.error()).find("needs the instance"), std::string::npos) << describe(none.error());
  EngineDevice engine;
  ASSERT_TRUE(engine.queue);
  AdoptedDevice wrong = engine.adopted();
  wrong.queue_family = 99;
  auto refused = adopt_context(wrong);
  ASSERT_FALSE(refused);
  EXPECT_NE(describe(refused.error()).find("no graphics"), std::string::npos) << describe(refused.error());
}

TEST_F(AdoptedDeviceTest, EachFrameIsCopiedIntoTheEnginesImage) {
  Scene scene = test_support::example_scene("phong_lights.json");
  RenderedFrame read_back = *render_scene(context(), scene, test_support::with_compiler({}));
  auto target = create_image(context(), {.width = uint32_t(scene.width), .height = uint32_t(scene.height),
                                         .format = VK_FORMAT_R16G16B16A16_SFLOAT,
                                         .usage = VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                                  VK_IMAGE_USAGE_SAMPLED_BIT});
  ASSERT_TRUE(target) << describe(target.error());
  auto renderer = test_support::create_renderer(context(), {.shader_compiler = test_support::with_compiler({}).shader_compiler});
  ASSERT_TRUE(renderer);
  const ImageTarget into{.image = target->handle(), .format = VK_FORMAT_R16G16B16A16_SFLOAT,
                         .width = uint32_t(scene.width), .height = uint32_t(scene.height),
                         .final_layout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL};
  RenderedFrame frame;
  for (int f = 0; f < 2; ++f) {
    ASSERT_TRUE(test_support::render(**renderer, scene, frame, {.target = into, .read_back = false}));
    EXPECT_TRUE(frame.hdr.empty());
    EXPECT_TRUE(frame.ldr.empty());
  }
  auto texels = read_image(context(), *target, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
  ASSERT_TRUE(texels) << describe(texels.error());
  ASSERT_EQ(texels->size(), read_back.hdr.size() * 2);
  std::vector<float> copied(read_back.hdr.size());
  for (size_t i = 0; i < copied.size(); ++i) {
    uint16_t h;
    std::memcpy(&h, texels->data() + 2 * i, 2);
    copied[i] = glm::unpackHalf1x16(h);
  }
  EXPECT_EQ(copied, read_back.hdr) << "the scene's exposure is 1: the target holds RenderedFrame::hdr";
}

TEST_F(AdoptedDeviceTest, ATargetOfAnotherSizeIsScaledAndABadTargetIsAnError) {
  Scene scene = test_support::example_scene("unlit.json");
  auto target = create_image(context(), {.width = 20, .height = 10, .format = VK_FORMAT_R8G8B8A8_UNORM,
                                         .usage = VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                                  VK_IMAGE_USAGE_SAMPLED_BIT});
  ASSERT_TRUE(target);
  auto renderer = test_support::create_renderer(context(), {.shader_compiler = test_support::with_compiler({}).shader_compiler});
  ASSERT_TRUE(renderer);
  RenderedFrame frame;
  ImageTarget into{.image = target->handle(), .format = VK_FORMAT_R8G8B8A8_UNORM, .width = 20, .height = 10,
                   .final_layout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL};
  ASSERT_TRUE(test_support::render(**renderer, scene, frame, {.target = into}));
  EXPECT_FALSE(frame.hdr.empty()) << "read back as well";
  auto texels = read_image(context(), *target, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
  ASSERT_TRUE(texels);
  EXPECT_TRUE(std::any_of(texels->begin(), texels->end(), [](std::byte b) { return b != std::byte{0}; }));
  into.format = VK_FORMAT_D32_SFLOAT;
  auto depth = test_support::render(**renderer, scene, frame, {.target = into});
  ASSERT_FALSE(depth);
  EXPECT_NE(depth.error().message.find("depth format"), std::string::npos) << depth.error().message;
  into.format = VK_FORMAT_BC1_RGB_UNORM_BLOCK;  // compressed: never a blit destination
  auto refused = test_support::render(**renderer, scene, frame, {.target = into});
  ASSERT_FALSE(refused);
  EXPECT_NE(refused.error().message.find("cannot blit"), std::string::npos) << refused.error().message;
  into.image = VK_NULL_HANDLE;
  refused = test_support::render(**renderer, scene, frame, {.target = into});
  ASSERT_FALSE(refused);
  EXPECT_NE(refused.error().message.find("no image"), std::string::npos);
}

}  // namespace
}  // namespace facet::runtime
