// The runtime's error value: what failed (a code), the VkResult when Vulkan
// said so, a one-line message and, where a choice was made, why each
// candidate was rejected (device selection). Runtime paths never throw.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "facet/result.h"

namespace facet::runtime {

enum class VkErrorCode : uint8_t {
  loader_missing,        // no Vulkan loader or it is older than 1.2
  layer_missing,         // the validation layer is not installed
  extension_missing,     // an instance extension we need is absent
  instance_failed,       // vkCreateInstance failed
  no_device,             // the selector matched no physical device
  device_failed,         // vkCreateDevice or a device query failed
  out_of_memory,         // no suitable memory type, or an allocation failed
  object_failed,         // creating a buffer, pipeline, pool, ... failed
  submit_failed,         // recording, submission or waiting failed
  invalid_argument,      // the caller passed something inconsistent
  compile_failed,        // HLSL did not compile (details in the Diagnostics)
};

struct VkError {
  VkErrorCode code = VkErrorCode::invalid_argument;
  VkResult result = VK_SUCCESS;  // VK_SUCCESS when Vulkan did not fail
  std::string message;
  std::vector<std::string> reasons;  // e.g. one line per rejected device
};

template <typename T>
using VkResultOf = Result<T, VkError>;

std::string_view error_code_name(VkErrorCode code);
// "message (VK_ERROR_...)" and one indented line per reason.
std::string describe(const VkError& error);
// "VK_ERROR_OUT_OF_DEVICE_MEMORY", ...; the number for codes it does not know.
std::string vk_result_name(VkResult result);

inline Unexpected<VkError> vk_failure(VkErrorCode code, std::string message, VkResult result = VK_SUCCESS,
                                      std::vector<std::string> reasons = {}) {
  return {VkError{code, result, std::move(message), std::move(reasons)}};
}

}  // namespace facet::runtime
