// A headless Vulkan 1.2 context: instance (no window system), one physical
// device chosen by a selector, a device with one compute-capable queue, a
// command pool and a timestamp query pool. Validation layers on request, with
// a debug-utils messenger that records every warning and error so that tests
// can assert there were none. shaderFloat16 is enabled where the device has it.
//
//   auto context = runtime::create_context({.validation = true});   // lavapipe
//   if (!context) { fmt::print("{}\n", runtime::describe(context.error())); return 1; }
//   ...
//   assert((*context)->messages().empty());
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "facet/runtime/vk_error.h"

namespace facet::runtime {

// One physical device as the loader reports it.
struct DeviceInfo {
  uint32_t index = 0;  // position in vkEnumeratePhysicalDevices
  std::string name;
  VkPhysicalDeviceType type = VK_PHYSICAL_DEVICE_TYPE_OTHER;
  uint32_t api_version = 0;
  float timestamp_period_ns = 0;    // nanoseconds per timestamp tick
  bool has_compute_queue = false;
  uint32_t timestamp_valid_bits = 0;  // of the first compute queue family; 0: no timestamps
  // VK_KHR_pipeline_executable_properties with its pipelineExecutableInfo
  // feature: the driver reports statistics of compiled pipelines
  // (facet/runtime/pipeline_statistics.h). lavapipe does not.
  bool pipeline_executable_info = false;
  // VK_KHR_maintenance4 and its feature, enabled where offered: a vertex
  // stage may write outputs the fragment stage does not read (as a Unity
  // variant's often does) without a validation warning.
  bool maintenance4 = false;
};

// "cpu", "discrete-gpu", ...
std::string_view device_type_name(VkPhysicalDeviceType type);
// "0: llvmpipe (LLVM 15.0.6, 256 bits) [cpu, Vulkan 1.3.230, timestamps 1 ns]"
std::string describe(const DeviceInfo& device);

// Which device a selector picks, as a pure function of the device list:
// ""            the first CPU device with a compute queue (lavapipe)
// "3"           the device at index 3
// "NVIDIA"      the first device whose name contains it (case-insensitive)
// The error lists every device and why it was rejected.
VkResultOf<uint32_t> select_device(const std::vector<DeviceInfo>& devices, const std::string& selector);

// The devices of this machine (through a short-lived instance, no layers).
VkResultOf<std::vector<DeviceInfo>> list_devices();

struct ContextOptions {
  std::string device;       // a selector for select_device
  bool validation = false;  // VK_LAYER_KHRONOS_validation + message recording
  // Enable VK_KHR_pipeline_executable_properties where the device offers it
  // (DeviceInfo::pipeline_executable_info); Context::pipeline_statistics()
  // says whether it is on. A device without it is no error.
  bool pipeline_statistics = false;
};

// What the validation messenger recorded (severity warning or error).
struct ValidationMessage {
  VkDebugUtilsMessageSeverityFlagBitsEXT severity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  std::string id_name;  // the VUID or message name
  std::string text;
};

// An engine's own Vulkan objects for adopt_context: facet draws with them
// and never destroys them.
struct AdoptedDevice {
  VkInstance instance = VK_NULL_HANDLE;
  VkPhysicalDevice physical_device = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  VkQueue queue = VK_NULL_HANDLE;  // of queue_family, which must have graphics
  uint32_t queue_family = 0;
  // What the engine enabled on `device`: facet draws what needs a feature
  // (geometryShader, tessellationShader, depthClamp, independentBlend for
  // the G-buffer) only when it is on, as with its own devices.
  VkPhysicalDeviceFeatures enabled_features{};
  bool shader_float16 = false;  // shaderFloat16 enabled
  bool maintenance4 = false;    // VK_KHR_maintenance4 and its feature enabled
  // Record warnings and errors in Context::messages() through a messenger
  // of facet's own: the instance must have VK_EXT_debug_utils enabled.
  bool record_messages = false;
};

// Owns every handle it holds and destroys them in reverse order (an adopted
// instance and device excepted: adopt_context). Not movable: the messenger
// keeps a pointer to it (create_context returns it on the heap).
class Context {
 public:
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  VkInstance instance() const { return instance_; }
  VkPhysicalDevice physical_device() const { return physical_; }
  VkDevice device() const { return device_; }
  VkQueue queue() const { return queue_; }
  uint32_t queue_family() const { return queue_family_; }
  VkCommandPool command_pool() const { return command_pool_; }
  VkQueryPool timestamp_pool() const { return timestamp_pool_; }  // 2 queries; null without timestamps
  const DeviceInfo& device_info() const { return info_; }
  bool validation() const { return validation_; }
  // True when the device was created with VK_KHR_pipeline_executable_properties
  // and pipelineExecutableInfo on (ContextOptions::pipeline_statistics).
  bool pipeline_statistics() const { return pipeline_statistics_; }
  // Whether the device has, and the context enabled, shaderFloat16: 16-bit
  // float arithmetic in shaders (kernels compiled with
  // backend::BackendOptions::hlsl_16bit_types). Off: such kernels must not run.
  bool shader_float16() const { return shader_float16_; }
  // The optional features ShaderLab can ask for, enabled where the device
  // has them: geometryShader (`#pragma geometry`), tessellationShader
  // (`#pragma hull`/`domain`, surface `tessellate:`), depthClamp (`ZClip
  // False`). The rest of the struct is off.
  const VkPhysicalDeviceFeatures& enabled_features() const { return features_; }

  // Every message of severity >= warning since creation (or the last clear).
  const std::vector<ValidationMessage>& messages() const { return messages_; }
  void clear_messages() { messages_.clear(); }
  // All messages, one per line, for test failure output.
  std::string messages_text() const;

 private:
  Context() = default;
  friend VkResultOf<std::unique_ptr<Context>> create_context(const ContextOptions& options);
  friend VkResultOf<std::unique_ptr<Context>> adopt_context(const AdoptedDevice& adopted);
  friend struct ContextBuilder;
  static VKAPI_ATTR VkBool32 VKAPI_CALL on_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                   VkDebugUtilsMessageTypeFlagsEXT types,
                                                   const VkDebugUtilsMessengerCallbackDataEXT* data, void* self);

  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  uint32_t queue_family_ = 0;
  VkCommandPool command_pool_ = VK_NULL_HANDLE;
  VkQueryPool timestamp_pool_ = VK_NULL_HANDLE;
  DeviceInfo info_;
  bool validation_ = false;
  bool owns_device_ = true;  // false: adopted, the engine destroys the instance and device
  bool pipeline_statistics_ = false;
  bool shader_float16_ = false;
  VkPhysicalDeviceFeatures features_{};
  std::vector<ValidationMessage> messages_;
};

// Creates the instance, picks the device and creates the device objects.
// Errors: loader_missing, layer_missing, extension_missing, instance_failed,
// no_device (with the reasons), device_failed, object_failed.
VkResultOf<std::unique_ptr<Context>> create_context(const ContextOptions& options);

// A context over an engine's instance, device and queue, with a command pool
// and timestamp queries of its own (destroyed with it; the engine's objects
// are not). Everything facet creates on it must go before the engine
// destroys its device: destroy the Context (and the Renderers using it)
// first. Queue submissions are facet's own: the engine must not use the
// queue from another thread while a render runs, and facet waits for the
// device to be idle (vkDeviceWaitIdle) when it frees a frame's targets, so
// the engine must not submit to its other queues from another thread while
// a render or the destruction of a Renderer or Context runs. Errors: object_failed,
// device_failed (no graphics on the queue family).
VkResultOf<std::unique_ptr<Context>> adopt_context(const AdoptedDevice& adopted);

}  // namespace facet::runtime
