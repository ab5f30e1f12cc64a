// Descriptor sets from pools that grow as sets are allocated: a frame whose
// draws share their frame, light and material sets needs far fewer than one
// of each per draw, so the pools are not sized up front.
#pragma once

#include <vulkan/vulkan.h>

#include <string>
#include <vector>

#include "facet/result.h"

namespace facet::runtime {

class DescriptorPools {
 public:
  explicit DescriptorPools(VkDevice device) : device_(device) {}
  ~DescriptorPools();
  DescriptorPools(const DescriptorPools&) = delete;
  DescriptorPools& operator=(const DescriptorPools&) = delete;

  // A set of `layout`, whose `bindings` say what it holds; a new pool is
  // made when the current one is full.
  Result<VkDescriptorSet, std::string> allocate(VkDescriptorSetLayout layout,
                                                const std::vector<VkDescriptorSetLayoutBinding>& bindings);

 private:
  Result<void, std::string> add_pool(const std::vector<VkDescriptorSetLayoutBinding>& bindings);

  VkDevice device_;
  std::vector<VkDescriptorPool> pools_;
};

}  // namespace facet::runtime
