#include "facet/runtime/vk_error.h"

#include <fmt/format.h>

namespace facet::runtime {

std::string_view error_code_name(VkErrorCode code) {
  switch (code) {
    case VkErrorCode::loader_missing: return "loader_missing";
    case VkErrorCode::layer_missing: return "layer_missing";
    case VkErrorCode::extension_missing: return "extension_missing";
    case VkErrorCode::instance_failed: return "instance_failed";
    case VkErrorCode::no_device: return "no_device";
    case VkErrorCode::device_failed: return "device_failed";
    case VkErrorCode::out_of_memory: return "out_of_memory";
    case VkErrorCode::object_failed: return "object_failed";
    case VkErrorCode::submit_failed: return "submit_failed";
    case VkErrorCode::invalid_argument: return "invalid_argument";
    case VkErrorCode::compile_failed: return "compile_failed";
  }
  return "unknown";
}

std::string vk_result_name(VkResult result) {
  switch (result) {
#define FACET_VK_RESULT(name) \
  case name: return #name;
    FACET_VK_RESULT(VK_SUCCESS)
    FACET_VK_RESULT(VK_NOT_READY)
    FACET_VK_RESULT(VK_TIMEOUT)
    FACET_VK_RESULT(VK_INCOMPLETE)
    FACET_VK_RESULT(VK_ERROR_OUT_OF_HOST_MEMORY)
    FACET_VK_RESULT(VK_ERROR_OUT_OF_DEVICE_MEMORY)
    FACET_VK_RESULT(VK_ERROR_INITIALIZATION_FAILED)
    FACET_VK_RESULT(VK_ERROR_DEVICE_LOST)
    FACET_VK_RESULT(VK_ERROR_MEMORY_MAP_FAILED)
    FACET_VK_RESULT(VK_ERROR_LAYER_NOT_PRESENT)
    FACET_VK_RESULT(VK_ERROR_EXTENSION_NOT_PRESENT)
    FACET_VK_RESULT(VK_ERROR_FEATURE_NOT_PRESENT)
    FACET_VK_RESULT(VK_ERROR_INCOMPATIBLE_DRIVER)
    FACET_VK_RESULT(VK_ERROR_TOO_MANY_OBJECTS)
    FACET_VK_RESULT(VK_ERROR_FORMAT_NOT_SUPPORTED)
    FACET_VK_RESULT(VK_ERROR_FRAGMENTED_POOL)
    FACET_VK_RESULT(VK_ERROR_OUT_OF_POOL_MEMORY)
    FACET_VK_RESULT(VK_ERROR_INVALID_SHADER_NV)
    FACET_VK_RESULT(VK_ERROR_UNKNOWN)
#undef FACET_VK_RESULT
    default: return fmt::format("VkResult({})", int(result));
  }
}

std::string describe(const VkError& error) {
  std::string text = error.message;
  if (error.result != VK_SUCCESS) text += fmt::format(" ({})", vk_result_name(error.result));
  for (const std::string& reason : error.reasons) text += "\n  " + reason;
  return text;
}

}  // namespace facet::runtime
