#include "render/descriptor_pools.h"

#include <algorithm>
#include <map>

#include "facet/runtime/vk_error.h"

namespace facet::runtime {
namespace {

// Sets a pool holds, and descriptors of each kind per set on average.
constexpr uint32_t kSetsPerPool = 256;
constexpr uint32_t kPerSet = 4;

}  // namespace

DescriptorPools::~DescriptorPools() {
  for (VkDescriptorPool pool : pools_) vkDestroyDescriptorPool(device_, pool, nullptr);
}

Result<void, std::string> DescriptorPools::add_pool(const std::vector<VkDescriptorSetLayoutBinding>& bindings) {
  std::map<VkDescriptorType, uint32_t> counts = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kSetsPerPool * kPerSet},
                                                 {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kSetsPerPool * kPerSet},
                                                 {VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, kSetsPerPool * kPerSet},
                                                 {VK_DESCRIPTOR_TYPE_SAMPLER, kSetsPerPool * kPerSet}};
  std::map<VkDescriptorType, uint32_t> needed;  // a set larger than the default share gets room for itself
  for (const VkDescriptorSetLayoutBinding& b : bindings) needed[b.descriptorType] += b.descriptorCount;
  for (auto [type, n] : needed) counts[type] = std::max(counts[type], n);
  std::vector<VkDescriptorPoolSize> sizes;
  for (auto [type, n] : counts) sizes.push_back({type, n});
  VkDescriptorPoolCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  info.maxSets = kSetsPerPool;
  info.poolSizeCount = uint32_t(sizes.size());
  info.pPoolSizes = sizes.data();
  VkDescriptorPool pool = VK_NULL_HANDLE;
  if (VkResult r = vkCreateDescriptorPool(device_, &info, nullptr, &pool); r != VK_SUCCESS) {
    return unexpected("cannot create a descriptor pool: " + vk_result_name(r));
  }
  pools_.push_back(pool);
  return {};
}

Result<VkDescriptorSet, std::string> DescriptorPools::allocate(VkDescriptorSetLayout layout,
                                                               const std::vector<VkDescriptorSetLayoutBinding>& bindings) {
  VkDescriptorSetAllocateInfo allocate{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  allocate.descriptorSetCount = 1;
  allocate.pSetLayouts = &layout;
  VkDescriptorSet set = VK_NULL_HANDLE;
  for (; current_ < pools_.size(); ++current_) {
    allocate.descriptorPool = pools_[current_];
    VkResult r = vkAllocateDescriptorSets(device_, &allocate, &set);
    if (r == VK_SUCCESS) return set;
    if (r != VK_ERROR_OUT_OF_POOL_MEMORY && r != VK_ERROR_FRAGMENTED_POOL) {
      return unexpected("cannot allocate a descriptor set: " + vk_result_name(r));
    }
  }
  if (Result<void, std::string> added = add_pool(bindings); !added) return unexpected(added.error());
  current_ = pools_.size() - 1;
  allocate.descriptorPool = pools_.back();
  if (VkResult r = vkAllocateDescriptorSets(device_, &allocate, &set); r != VK_SUCCESS) {
    return unexpected("cannot allocate a descriptor set: " + vk_result_name(r));
  }
  return set;
}

void DescriptorPools::reset() {
  for (VkDescriptorPool pool : pools_) vkResetDescriptorPool(device_, pool, 0);
  current_ = 0;
}

}  // namespace facet::runtime
