// Instance creation and physical-device queries shared by list_devices() and
// create_context().
#pragma once

#include <vulkan/vulkan.h>

#include <optional>
#include <vector>

#include "facet/runtime/vulkan_context.h"

namespace facet::runtime {

inline constexpr uint32_t kApiVersion = VK_API_VERSION_1_2;
inline constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

// A headless instance; with validation, the layer and VK_EXT_debug_utils are
// enabled and `messenger` (if given) is chained so that instance creation
// itself is reported. The caller destroys the instance.
VkResultOf<VkInstance> create_instance(bool validation, const VkDebugUtilsMessengerCreateInfoEXT* messenger);

// The first queue family with graphics and compute, else the first with
// compute, if any.
std::optional<uint32_t> compute_queue_family(VkPhysicalDevice device);

DeviceInfo query_device(VkPhysicalDevice device, uint32_t index);

VkResultOf<std::vector<VkPhysicalDevice>> physical_devices(VkInstance instance);

}  // namespace facet::runtime
