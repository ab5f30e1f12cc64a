// Device description and choice: pure functions over DeviceInfo, plus the
// queries that fill it.
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>

#include "facet/runtime/vulkan_context.h"
#include "facet/support/text.h"
#include "vulkan/device_query.h"

namespace facet::runtime {
namespace {

std::optional<uint32_t> parse_index(const std::string& selector) {
  uint32_t value = 0;
  auto [end, ec] = std::from_chars(selector.data(), selector.data() + selector.size(), value);
  if (ec != std::errc() || end != selector.data() + selector.size()) return std::nullopt;
  return value;
}

// Why `device` cannot run the runtime at all; empty when it can.
std::string unusable_reason(const DeviceInfo& device) {
  if (!device.has_compute_queue) return "no compute queue";
  if (device.api_version < kApiVersion) {
    return fmt::format("Vulkan {}.{} < 1.2", VK_API_VERSION_MAJOR(device.api_version),
                       VK_API_VERSION_MINOR(device.api_version));
  }
  return {};
}

std::vector<VkQueueFamilyProperties> queue_families(VkPhysicalDevice device) {
  uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
  families.resize(count);
  return families;
}

bool offers_extension(VkPhysicalDevice device, const char* name) {
  uint32_t count = 0;
  if (vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr) != VK_SUCCESS) return false;
  std::vector<VkExtensionProperties> extensions(count);
  if (vkEnumerateDeviceExtensionProperties(device, nullptr, &count, extensions.data()) != VK_SUCCESS) return false;
  return std::any_of(extensions.begin(), extensions.begin() + count,
                     [&](const VkExtensionProperties& e) { return std::string_view(e.extensionName) == name; });
}

// `extension` is offered and its feature struct `Feature` (of `type`) has
// `member` on (vkGetPhysicalDeviceFeatures2 is core from Vulkan 1.1; older
// devices are rejected by select_device anyway).
template <typename Feature>
bool offers_feature(VkPhysicalDevice device, uint32_t api_version, const char* extension, VkStructureType type,
                    VkBool32 Feature::*member) {
  if (api_version < VK_API_VERSION_1_1) return false;
  if (!offers_extension(device, extension)) return false;
  Feature feature{};
  feature.sType = type;
  VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
  features.pNext = &feature;
  vkGetPhysicalDeviceFeatures2(device, &features);
  return feature.*member == VK_TRUE;
}

std::string rejection(const DeviceInfo& device, const std::string& why) {
  return fmt::format("{}: rejected, {}", describe(device), why);
}

}  // namespace

std::string_view device_type_name(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_OTHER: return "other";
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return "integrated-gpu";
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return "discrete-gpu";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return "virtual-gpu";
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return "cpu";
    default: return "unknown";
  }
}

std::string describe(const DeviceInfo& device) {
  std::string timestamps = device.timestamp_valid_bits
                               ? fmt::format("timestamps {} ns", device.timestamp_period_ns)
                               : std::string("no timestamps");
  return fmt::format("{}: {} [{}, Vulkan {}.{}.{}, {}]", device.index, device.name, device_type_name(device.type),
                     VK_API_VERSION_MAJOR(device.api_version), VK_API_VERSION_MINOR(device.api_version),
                     VK_API_VERSION_PATCH(device.api_version), timestamps);
}

VkResultOf<uint32_t> select_device(const std::vector<DeviceInfo>& devices, const std::string& selector) {
  std::optional<uint32_t> index = parse_index(selector);
  std::string wanted = lower(selector);
  std::vector<std::string> reasons;
  for (const DeviceInfo& device : devices) {
    std::string why;
    if (selector.empty() && device.type != VK_PHYSICAL_DEVICE_TYPE_CPU) {
      why = "not a CPU device (the default is lavapipe)";
    } else if (index && device.index != *index) {
      why = fmt::format("index is not {}", *index);
    } else if (!index && !selector.empty() && lower(device.name).find(wanted) == std::string::npos) {
      why = fmt::format("name does not contain '{}'", selector);
    } else {
      why = unusable_reason(device);
    }
    if (why.empty()) return device.index;
    reasons.push_back(rejection(device, why));
  }
  if (devices.empty()) reasons.push_back("the Vulkan loader reports no physical device");
  std::string what = selector.empty() ? std::string("no CPU Vulkan device (lavapipe: install mesa-vulkan-drivers)")
                                      : fmt::format("no Vulkan device matches '{}'", selector);
  return vk_failure(VkErrorCode::no_device, what, VK_SUCCESS, std::move(reasons));
}

std::optional<uint32_t> compute_queue_family(VkPhysicalDevice device) {
  // A family with graphics too, where there is one, so that the renderer
  // draws on the same queue the evaluator dispatches on.
  std::vector<VkQueueFamilyProperties> families = queue_families(device);
  constexpr VkQueueFlags kBoth = VK_QUEUE_COMPUTE_BIT | VK_QUEUE_GRAPHICS_BIT;
  for (uint32_t i = 0; i < families.size(); ++i) {
    if ((families[i].queueFlags & kBoth) == kBoth) return i;
  }
  for (uint32_t i = 0; i < families.size(); ++i) {
    if (families[i].queueFlags & VK_QUEUE_COMPUTE_BIT) return i;
  }
  return std::nullopt;
}

DeviceInfo query_device(VkPhysicalDevice device, uint32_t index) {
  VkPhysicalDeviceProperties properties{};
  vkGetPhysicalDeviceProperties(device, &properties);
  DeviceInfo info;
  info.index = index;
  info.name = properties.deviceName;
  info.type = properties.deviceType;
  info.api_version = properties.apiVersion;
  info.timestamp_period_ns = properties.limits.timestampPeriod;
  if (std::optional<uint32_t> family = compute_queue_family(device)) {
    info.has_compute_queue = true;
    info.timestamp_valid_bits = queue_families(device)[*family].timestampValidBits;
  }
  info.pipeline_executable_info = offers_feature(
      device, info.api_version, VK_KHR_PIPELINE_EXECUTABLE_PROPERTIES_EXTENSION_NAME,
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PIPELINE_EXECUTABLE_PROPERTIES_FEATURES_KHR,
      &VkPhysicalDevicePipelineExecutablePropertiesFeaturesKHR::pipelineExecutableInfo);
  info.maintenance4 = offers_feature(device, info.api_version, VK_KHR_MAINTENANCE_4_EXTENSION_NAME,
                                     VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_4_FEATURES,
                                     &VkPhysicalDeviceMaintenance4Features::maintenance4);
  return info;
}

VkResultOf<std::vector<VkPhysicalDevice>> physical_devices(VkInstance instance) {
  uint32_t count = 0;
  VkResult result = vkEnumeratePhysicalDevices(instance, &count, nullptr);
  std::vector<VkPhysicalDevice> devices(count);
  if (result == VK_SUCCESS && count) result = vkEnumeratePhysicalDevices(instance, &count, devices.data());
  if (result != VK_SUCCESS && result != VK_INCOMPLETE) {
    return vk_failure(VkErrorCode::device_failed, "cannot enumerate physical devices", result);
  }
  devices.resize(count);
  return devices;
}

VkResultOf<std::vector<DeviceInfo>> list_devices() {
  VkResultOf<VkInstance> instance = create_instance(false, nullptr);
  if (!instance) return unexpected(instance.error());
  VkResultOf<std::vector<VkPhysicalDevice>> handles = physical_devices(*instance);
  std::vector<DeviceInfo> devices;
  if (handles) {
    for (uint32_t i = 0; i < handles->size(); ++i) devices.push_back(query_device((*handles)[i], i));
  }
  vkDestroyInstance(*instance, nullptr);
  if (!handles) return unexpected(handles.error());
  return devices;
}

}  // namespace facet::runtime
