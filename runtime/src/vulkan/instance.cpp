// The headless instance: Vulkan 1.2, no surface extensions, and on request
// the Khronos validation layer with VK_EXT_debug_utils.
#include <fmt/format.h>

#include <algorithm>
#include <cstring>

#include "vulkan/device_query.h"

namespace facet::runtime {
namespace {

bool has_layer(const char* name) {
  uint32_t count = 0;
  if (vkEnumerateInstanceLayerProperties(&count, nullptr) != VK_SUCCESS) return false;
  std::vector<VkLayerProperties> layers(count);
  if (vkEnumerateInstanceLayerProperties(&count, layers.data()) != VK_SUCCESS) return false;
  return std::any_of(layers.begin(), layers.begin() + count,
                     [&](const VkLayerProperties& l) { return std::strcmp(l.layerName, name) == 0; });
}

// In the loader itself or in `layer`.
bool has_extension(const char* name, const char* layer) {
  for (const char* where : {static_cast<const char*>(nullptr), layer}) {
    uint32_t count = 0;
    if (vkEnumerateInstanceExtensionProperties(where, &count, nullptr) != VK_SUCCESS) continue;
    std::vector<VkExtensionProperties> extensions(count);
    if (vkEnumerateInstanceExtensionProperties(where, &count, extensions.data()) != VK_SUCCESS) continue;
    if (std::any_of(extensions.begin(), extensions.begin() + count,
                    [&](const VkExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; })) {
      return true;
    }
    if (!layer) break;
  }
  return false;
}

VkResultOf<void> check_loader() {
  uint32_t version = 0;
  if (vkEnumerateInstanceVersion(&version) != VK_SUCCESS || version < kApiVersion) {
    return vk_failure(VkErrorCode::loader_missing,
                      fmt::format("the Vulkan loader supports {}.{}; facet needs 1.2", VK_API_VERSION_MAJOR(version),
                                  VK_API_VERSION_MINOR(version)));
  }
  return {};
}

}  // namespace

VkResultOf<VkInstance> create_instance(bool validation, const VkDebugUtilsMessengerCreateInfoEXT* messenger) {
  if (VkResultOf<void> loader = check_loader(); !loader) return unexpected(loader.error());
  std::vector<const char*> layers, extensions;
  if (validation) {
    if (!has_layer(kValidationLayer)) {
      return vk_failure(VkErrorCode::layer_missing,
                        fmt::format("validation was asked for but {} is not installed (Debian: vulkan-validationlayers)",
                                    kValidationLayer));
    }
    if (!has_extension(VK_EXT_DEBUG_UTILS_EXTENSION_NAME, kValidationLayer)) {
      return vk_failure(VkErrorCode::extension_missing,
                        fmt::format("validation needs {}, which neither the loader nor the layer offers",
                                    VK_EXT_DEBUG_UTILS_EXTENSION_NAME));
    }
    layers.push_back(kValidationLayer);
    extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  }
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "facet";
  app.pEngineName = "facet";
  app.apiVersion = kApiVersion;
  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pNext = validation ? messenger : nullptr;
  info.pApplicationInfo = &app;
  info.enabledLayerCount = uint32_t(layers.size());
  info.ppEnabledLayerNames = layers.data();
  info.enabledExtensionCount = uint32_t(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  VkInstance instance = VK_NULL_HANDLE;
  if (VkResult result = vkCreateInstance(&info, nullptr, &instance); result != VK_SUCCESS) {
    std::string what = result == VK_ERROR_INCOMPATIBLE_DRIVER
                           ? "no Vulkan 1.2 driver is installed (lavapipe: mesa-vulkan-drivers)"
                           : "vkCreateInstance failed";
    return vk_failure(VkErrorCode::instance_failed, what, result);
  }
  return instance;
}

}  // namespace facet::runtime
