// create_context: instance -> messenger -> physical device -> device and
// queue -> command pool and timestamp queries. Each step returns an error
// value; whatever was created before a failure is destroyed by ~Context.
#include <fmt/format.h>

#include <algorithm>
#include <vector>

#include "facet/runtime/vulkan_context.h"
#include "vulkan/device_query.h"

namespace facet::runtime {

struct ContextBuilder {
  static VkDebugUtilsMessengerCreateInfoEXT messenger_info(Context& context) {
    VkDebugUtilsMessengerCreateInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    info.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    info.pfnUserCallback = &Context::on_message;
    info.pUserData = &context;
    return info;
  }

  static VkResultOf<void> create_messenger(Context& context, const VkDebugUtilsMessengerCreateInfoEXT& info) {
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(context.instance_, "vkCreateDebugUtilsMessengerEXT"));
    if (!create) return vk_failure(VkErrorCode::extension_missing, "vkCreateDebugUtilsMessengerEXT is not available");
    if (VkResult result = create(context.instance_, &info, nullptr, &context.messenger_); result != VK_SUCCESS) {
      return vk_failure(VkErrorCode::object_failed, "cannot create the validation messenger", result);
    }
    return {};
  }

  static VkResultOf<void> pick_device(Context& context, const std::string& selector) {
    VkResultOf<std::vector<VkPhysicalDevice>> handles = physical_devices(context.instance_);
    if (!handles) return unexpected(handles.error());
    std::vector<DeviceInfo> infos;
    for (uint32_t i = 0; i < handles->size(); ++i) infos.push_back(query_device((*handles)[i], i));
    VkResultOf<uint32_t> chosen = select_device(infos, selector);
    if (!chosen) return unexpected(chosen.error());
    context.physical_ = (*handles)[*chosen];
    context.info_ = infos[*chosen];
    return {};
  }

  // shaderFloat16 (Vulkan 1.2 core, VkPhysicalDeviceShaderFloat16Int8Features)
  // where the device has it, so that 16-bit kernels (BackendOptions::
  // hlsl_16bit_types) run; Context::shader_float16 says whether it is on.
  static bool supports_float16(const Context& context) {
    if (context.info_.api_version < VK_API_VERSION_1_2) return false;
    VkPhysicalDeviceShaderFloat16Int8Features float16{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_FLOAT16_INT8_FEATURES};
    VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    features.pNext = &float16;
    vkGetPhysicalDeviceFeatures2(context.physical_, &features);
    return float16.shaderFloat16 == VK_TRUE;
  }

  // pipeline_statistics: VK_KHR_pipeline_executable_properties and its
  // feature, where the device offers them.
  static VkResultOf<void> create_device(Context& context, bool pipeline_statistics) {
    context.queue_family_ = compute_queue_family(context.physical_).value_or(0);  // select_device checked it
    float priority = 1.0f;
    VkDeviceQueueCreateInfo queue{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queue.queueFamilyIndex = context.queue_family_;
    queue.queueCount = 1;
    queue.pQueuePriorities = &priority;
    VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    info.queueCreateInfoCount = 1;
    info.pQueueCreateInfos = &queue;
    std::vector<const char*> extensions;
    VkPhysicalDevicePipelineExecutablePropertiesFeaturesKHR executable_info{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PIPELINE_EXECUTABLE_PROPERTIES_FEATURES_KHR};
    context.pipeline_statistics_ = pipeline_statistics && context.info_.pipeline_executable_info;
    if (context.pipeline_statistics_) {
      executable_info.pipelineExecutableInfo = VK_TRUE;
      executable_info.pNext = const_cast<void*>(info.pNext);
      info.pNext = &executable_info;
      extensions.push_back(VK_KHR_PIPELINE_EXECUTABLE_PROPERTIES_EXTENSION_NAME);
    }
    VkPhysicalDeviceMaintenance4Features maintenance4{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_4_FEATURES};
    if (context.info_.maintenance4) {
      maintenance4.maintenance4 = VK_TRUE;
      maintenance4.pNext = const_cast<void*>(info.pNext);
      info.pNext = &maintenance4;
      extensions.push_back(VK_KHR_MAINTENANCE_4_EXTENSION_NAME);
    }
    info.enabledExtensionCount = uint32_t(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    VkPhysicalDeviceShaderFloat16Int8Features float16{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_FLOAT16_INT8_FEATURES};
    context.shader_float16_ = supports_float16(context);
    float16.shaderFloat16 = VK_TRUE;
    if (context.shader_float16_) {
      float16.pNext = const_cast<void*>(info.pNext);
      info.pNext = &float16;
    }
    VkPhysicalDeviceFeatures supported{};
    vkGetPhysicalDeviceFeatures(context.physical_, &supported);
    context.features_ = {};
    context.features_.geometryShader = supported.geometryShader;
    context.features_.tessellationShader = supported.tessellationShader;
    context.features_.depthClamp = supported.depthClamp;
    context.features_.independentBlend = supported.independentBlend;  // G-buffer targets a pass does not write
    info.pEnabledFeatures = &context.features_;
    if (VkResult result = vkCreateDevice(context.physical_, &info, nullptr, &context.device_); result != VK_SUCCESS) {
      return vk_failure(VkErrorCode::device_failed, fmt::format("cannot create a device on {}", context.info_.name),
                        result);
    }
    vkGetDeviceQueue(context.device_, context.queue_family_, 0, &context.queue_);
    return {};
  }

  static VkResultOf<void> create_pools(Context& context) {
    VkCommandPoolCreateInfo pool{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pool.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
    pool.queueFamilyIndex = context.queue_family_;
    if (VkResult result = vkCreateCommandPool(context.device_, &pool, nullptr, &context.command_pool_);
        result != VK_SUCCESS) {
      return vk_failure(VkErrorCode::object_failed, "cannot create a command pool", result);
    }
    if (context.info_.timestamp_valid_bits == 0) return {};
    VkQueryPoolCreateInfo queries{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    queries.queryType = VK_QUERY_TYPE_TIMESTAMP;
    queries.queryCount = 2;
    if (VkResult result = vkCreateQueryPool(context.device_, &queries, nullptr, &context.timestamp_pool_);
        result != VK_SUCCESS) {
      return vk_failure(VkErrorCode::object_failed, "cannot create a timestamp query pool", result);
    }
    return {};
  }
};

VkResultOf<std::unique_ptr<Context>> create_context(const ContextOptions& options) {
  std::unique_ptr<Context> context(new Context);
  context->validation_ = options.validation;
  VkDebugUtilsMessengerCreateInfoEXT messenger = ContextBuilder::messenger_info(*context);
  VkResultOf<VkInstance> instance = create_instance(options.validation, &messenger);
  if (!instance) return unexpected(instance.error());
  context->instance_ = *instance;
  if (options.validation) FACET_TRY(ContextBuilder::create_messenger(*context, messenger));
  FACET_TRY(ContextBuilder::pick_device(*context, options.device));
  FACET_TRY(ContextBuilder::create_device(*context, options.pipeline_statistics));
  FACET_TRY(ContextBuilder::create_pools(*context));
  return context;
}

VkResultOf<std::unique_ptr<Context>> adopt_context(const AdoptedDevice& adopted) {
  if (!adopted.instance || !adopted.physical_device || !adopted.device || !adopted.queue) {
    return vk_failure(VkErrorCode::object_failed, "adopt_context needs the instance, physical device, device and queue");
  }
  std::unique_ptr<Context> context(new Context);
  context->owns_device_ = false;
  context->instance_ = adopted.instance;
  context->physical_ = adopted.physical_device;
  context->device_ = adopted.device;
  context->queue_ = adopted.queue;
  context->queue_family_ = adopted.queue_family;
  uint32_t index = 0;
  if (VkResultOf<std::vector<VkPhysicalDevice>> handles = physical_devices(adopted.instance)) {
    auto it = std::find(handles->begin(), handles->end(), adopted.physical_device);
    if (it != handles->end()) index = uint32_t(it - handles->begin());
  }
  context->info_ = query_device(adopted.physical_device, index);
  context->info_.maintenance4 = adopted.maintenance4;
  context->info_.pipeline_executable_info = false;
  uint32_t family_count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(adopted.physical_device, &family_count, nullptr);
  std::vector<VkQueueFamilyProperties> families(family_count);
  vkGetPhysicalDeviceQueueFamilyProperties(adopted.physical_device, &family_count, families.data());
  if (adopted.queue_family >= family_count || !(families[adopted.queue_family].queueFlags & VK_QUEUE_GRAPHICS_BIT)) {
    return vk_failure(VkErrorCode::device_failed,
                      fmt::format("queue family {} of {} has no graphics: facet draws on it", adopted.queue_family,
                                  context->info_.name));
  }
  context->info_.timestamp_valid_bits = families[adopted.queue_family].timestampValidBits;
  context->features_ = adopted.enabled_features;
  context->shader_float16_ = adopted.shader_float16;
  if (adopted.record_messages) {
    context->validation_ = true;
    FACET_TRY(ContextBuilder::create_messenger(*context, ContextBuilder::messenger_info(*context)));
  }
  FACET_TRY(ContextBuilder::create_pools(*context));
  return context;
}

Context::~Context() {
  if (device_) {
    vkDeviceWaitIdle(device_);
    if (timestamp_pool_) vkDestroyQueryPool(device_, timestamp_pool_, nullptr);
    if (command_pool_) vkDestroyCommandPool(device_, command_pool_, nullptr);
    if (owns_device_) vkDestroyDevice(device_, nullptr);
  }
  if (messenger_) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy) destroy(instance_, messenger_, nullptr);
  }
  if (instance_ && owns_device_) vkDestroyInstance(instance_, nullptr);
}

VKAPI_ATTR VkBool32 VKAPI_CALL Context::on_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                   VkDebugUtilsMessageTypeFlagsEXT,
                                                   const VkDebugUtilsMessengerCallbackDataEXT* data, void* self) {
  if (severity < VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT || !self || !data) return VK_FALSE;
  ValidationMessage message;
  message.severity = severity;
  message.id_name = data->pMessageIdName ? data->pMessageIdName : "";
  message.text = data->pMessage ? data->pMessage : "";
  static_cast<Context*>(self)->messages_.push_back(std::move(message));
  return VK_FALSE;  // never abort the call that triggered the message
}

std::string Context::messages_text() const {
  std::string text;
  for (const ValidationMessage& m : messages_) {
    const char* level = m.severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT ? "error" : "warning";
    text += fmt::format("{} [{}] {}\n", level, m.id_name, m.text);
  }
  return text;
}

}  // namespace facet::runtime
