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
  // Frees every set (none may be in use by the GPU): later allocations
  // fill the pools there are before a new one is made.
  void reset();
  size_t pools_created() const { return pools_.size(); }

 private:
  Result<void, std::string> add_pool(const std::vector<VkDescriptorSetLayoutBinding>& bindings);

  VkDevice device_;
  std::vector<VkDescriptorPool> pools_;
  size_t current_ = 0;  // the pool allocations come from; those before it are full
};

}  // namespace facet::runtime
