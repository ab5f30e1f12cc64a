#include "facet/runtime/vulkan_context.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <optional>

#include "facet/runtime/buffer.h"
#include "facet/runtime/compute.h"
#include "unit/runtime/context_fixture.h"

namespace facet::runtime {
namespace {

DeviceInfo device(uint32_t index, std::string name, VkPhysicalDeviceType type, bool compute = true) {
  DeviceInfo d;
  d.index = index;
  d.name = std::move(name);
  d.type = type;
  d.api_version = VK_API_VERSION_1_3;
  d.has_compute_queue = compute;
  return d;
}

const std::vector<DeviceInfo> kMachine = {
    device(0, "NVIDIA H100", VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU),
    device(1, "Broken GPU", VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU, false),
    device(2, "llvmpipe (LLVM 15.0.6, 256 bits)", VK_PHYSICAL_DEVICE_TYPE_CPU),
};

TEST(SelectDeviceTest, DefaultIsTheCpuDevice) {
  VkResultOf<uint32_t> chosen = select_device(kMachine, "");
  ASSERT_TRUE(chosen) << describe(chosen.error());
  EXPECT_EQ(*chosen, 2u);
}

TEST(SelectDeviceTest, ByIndex) {
  VkResultOf<uint32_t> chosen = select_device(kMachine, "0");
  ASSERT_TRUE(chosen) << describe(chosen.error());
  EXPECT_EQ(*chosen, 0u);
}

TEST(SelectDeviceTest, ByCaseInsensitiveNameSubstring) {
  VkResultOf<uint32_t> chosen = select_device(kMachine, "h100");
  ASSERT_TRUE(chosen) << describe(chosen.error());
  EXPECT_EQ(*chosen, 0u);
}

TEST(SelectDeviceTest, DeviceWithoutComputeQueueIsRejectedWithTheReason) {
  VkResultOf<uint32_t> chosen = select_device(kMachine, "broken");
  ASSERT_FALSE(chosen);
  EXPECT_EQ(chosen.error().code, VkErrorCode::no_device);
  std::string text = describe(chosen.error());
  EXPECT_NE(text.find("no Vulkan device matches 'broken'"), std::string::npos) << text;
  EXPECT_NE(text.find("Broken GPU [integrated-gpu, Vulkan 1.3.0, no timestamps]: rejected, no compute queue"),
            std::string::npos)
      << text;
}

TEST(SelectDeviceTest, NoMatchListsEveryDevice) {
  VkResultOf<uint32_t> chosen = select_device(kMachine, "7");
  ASSERT_FALSE(chosen);
  ASSERT_EQ(chosen.error().reasons.size(), kMachine.size());
  EXPECT_NE(chosen.error().reasons[2].find("index is not 7"), std::string::npos) << describe(chosen.error());
}

TEST(SelectDeviceTest, NoCpuDeviceSaysHowToGetLavapipe) {
  VkResultOf<uint32_t> chosen = select_device({kMachine[0]}, "");
  ASSERT_FALSE(chosen);
  EXPECT_NE(chosen.error().message.find("mesa-vulkan-drivers"), std::string::npos) << describe(chosen.error());
}

TEST(VulkanContextTest, ListsAtLeastOneDevice) {
  VkResultOf<std::vector<DeviceInfo>> devices = list_devices();
  ASSERT_TRUE(devices) << describe(devices.error());
  ASSERT_FALSE(devices->empty());
  for (const DeviceInfo& d : *devices) {
    EXPECT_FALSE(d.name.empty());
    EXPECT_GT(d.api_version, 0u);
  }
}

TEST(VulkanContextTest, CreatesLavapipeWithValidationAndReportsNoMessages) {
  VkResultOf<std::unique_ptr<Context>> context = create_context({.validation = true});
  ASSERT_TRUE(context) << describe(context.error());
  const Context& c = **context;
  EXPECT_EQ(c.device_info().type, VK_PHYSICAL_DEVICE_TYPE_CPU);
  EXPECT_NE(c.device_info().name.find("llvmpipe"), std::string::npos) << describe(c.device_info());
  EXPECT_TRUE(c.validation());
  EXPECT_NE(c.device(), VK_NULL_HANDLE);
  EXPECT_NE(c.queue(), VK_NULL_HANDLE);
  EXPECT_TRUE(c.messages().empty()) << c.messages_text();
}

// The zero-message assertions of the other tests mean something only if the
// messenger does record: a buffer with no usage bits is invalid usage.
// shaderFloat16 is enabled exactly where the device has it (lavapipe does),
// and the context says so.
TEST(VulkanContextTest, EnablesShaderFloat16WhereTheDeviceHasIt) {
  VkResultOf<std::unique_ptr<Context>> context = create_context({.validation = true});
  ASSERT_TRUE(context) << describe(context.error());
  VkPhysicalDeviceShaderFloat16Int8Features float16{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_FLOAT16_INT8_FEATURES};
  VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
  features.pNext = &float16;
  vkGetPhysicalDeviceFeatures2((*context)->physical_device(), &features);
  EXPECT_EQ((*context)->shader_float16(), float16.shaderFloat16 == VK_TRUE);
  if ((*context)->device_info().name.find("llvmpipe") != std::string::npos) {
    EXPECT_TRUE((*context)->shader_float16());
  }
  EXPECT_TRUE((*context)->messages().empty()) << (*context)->messages_text();
}

TEST(VulkanContextTest, ValidationMessengerRecordsAnInvalidCall) {
  VkResultOf<std::unique_ptr<Context>> context = create_context({.validation = true});
  ASSERT_TRUE(context) << describe(context.error());
  Context& c = **context;
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = 16;
  info.usage = 0;
  VkBuffer buffer = VK_NULL_HANDLE;
  if (vkCreateBuffer(c.device(), &info, nullptr, &buffer) == VK_SUCCESS) vkDestroyBuffer(c.device(), buffer, nullptr);
  ASSERT_FALSE(c.messages().empty());
  EXPECT_NE(c.messages_text().find("VUID-VkBufferCreateInfo-usage"), std::string::npos) << c.messages_text();
  EXPECT_EQ(c.messages().front().severity, VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT);
}

TEST(VulkanContextTest, UnknownDeviceNameIsAClearError) {
  VkResultOf<std::unique_ptr<Context>> context = create_context({.device = "no-such-gpu-xyz", .validation = true});
  ASSERT_FALSE(context);
  EXPECT_EQ(context.error().code, VkErrorCode::no_device);
  std::string text = describe(context.error());
  EXPECT_NE(text.find("no Vulkan device matches 'no-such-gpu-xyz'"), std::string::npos) << text;
  EXPECT_NE(text.find("llvmpipe"), std::string::npos) << "the rejected devices are listed:\n" << text;
}

// Sets an environment variable for one scope (the loader reads its search
// paths on each call).
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    setenv(name, value, 1);
  }
  ~ScopedEnv() {
    if (old_) setenv(name_, old_->c_str(), 1);
    else unsetenv(name_);
  }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

 private:
  const char* name_;
  std::optional<std::string> old_;
};

TEST(VulkanContextTest, MissingValidationLayerIsAClearError) {
  ScopedEnv no_layers("VK_LAYER_PATH", "/nonexistent-facet-layers");
  VkResultOf<std::unique_ptr<Context>> context = create_context({.validation = true});
  ASSERT_FALSE(context);
  EXPECT_EQ(context.error().code, VkErrorCode::layer_missing);
  EXPECT_NE(describe(context.error()).find("VK_LAYER_KHRONOS_validation"), std::string::npos)
      << describe(context.error());
}

TEST(VulkanContextTest, NoDriverIsAClearError) {
  ScopedEnv no_drivers("VK_ICD_FILENAMES", "/nonexistent-facet-icd.json");
  VkResultOf<std::unique_ptr<Context>> context = create_context({});
  ASSERT_FALSE(context);
  EXPECT_EQ(context.error().code, VkErrorCode::instance_failed) << describe(context.error());
  EXPECT_NE(context.error().message.find("no Vulkan 1.2 driver"), std::string::npos) << describe(context.error());
}

class VulkanComputeTest : public test_support::LavapipeTest {};

TEST_F(VulkanComputeTest, ZeroSizedBufferIsInvalid) {
  VkResultOf<Buffer> buffer = create_storage_buffer(context(), 0);
  ASSERT_FALSE(buffer);
  EXPECT_EQ(buffer.error().code, VkErrorCode::invalid_argument);
}

TEST_F(VulkanComputeTest, BufferIsMappedAndKeepsItsContents) {
  VkResultOf<Buffer> buffer = create_storage_buffer(context(), 64);
  ASSERT_TRUE(buffer) << describe(buffer.error());
  ASSERT_NE(buffer->data(), nullptr);
  std::memset(buffer->data(), 0x5a, 64);
  Buffer moved = std::move(*buffer);
  EXPECT_EQ(static_cast<unsigned char*>(moved.data())[63], 0x5a);
  EXPECT_EQ(buffer->data(), nullptr);
}

TEST_F(VulkanComputeTest, NonSpirvIsRejectedBeforeVulkanSeesIt) {
  VkResultOf<ComputePipeline> pipeline = create_compute_pipeline(context(), {1, 2, 3, 4, 5}, {});
  ASSERT_FALSE(pipeline);
  EXPECT_EQ(pipeline.error().code, VkErrorCode::invalid_argument);
}

}  // namespace
}  // namespace facet::runtime
