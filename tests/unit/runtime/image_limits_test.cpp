// Images past the device's limits are refused by create_image with an
// error naming the limit, before Vulkan sees them (lavapipe crashed inside
// vkCreateImage on a 1 x 10^6 image, and the validation layer reports it).
#include <gtest/gtest.h>

#include <string>

#include "facet/runtime/image.h"
#include "unit/runtime/context_fixture.h"

namespace facet::runtime {
namespace {

class ImageLimitsTest : public test_support::LavapipeTest {
 protected:
  static VkPhysicalDeviceLimits limits() {
    VkPhysicalDeviceProperties properties{};
    vkGetPhysicalDeviceProperties(context().physical_device(), &properties);
    return properties.limits;
  }
};

TEST_F(ImageLimitsTest, SidesPastMaxImageDimension2DAreAnErrorNamingTheLimit) {
  uint32_t max = limits().maxImageDimension2D;
  std::string named = "this device's maxImageDimension2D (" + std::to_string(max) + ")";
  for (auto [width, height] : {std::pair{1000000u, 1u}, std::pair{1u, 1000000u}, std::pair{max + 1, 1u}}) {
    VkResultOf<Image> image = create_image(context(), {.width = width, .height = height,
                                                       .usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT});
    ASSERT_FALSE(image) << width << "x" << height;
    EXPECT_EQ(image.error().code, VkErrorCode::invalid_argument);
    EXPECT_NE(image.error().message.find(named), std::string::npos) << image.error().message;
  }
  EXPECT_TRUE(create_image(context(), {.width = 16, .height = 16}));  // the control: a small one is made
}

TEST_F(ImageLimitsTest, MoreMipsThanTheChainHasAreAnError) {
  VkResultOf<Image> image = create_image(context(), {.width = 4, .height = 4, .mips = 4});
  ASSERT_FALSE(image);
  EXPECT_NE(image.error().message.find("4 mips are more than a 4x4 image has (3)"), std::string::npos)
      << image.error().message;
}

TEST_F(ImageLimitsTest, LayersPastMaxImageArrayLayersAreAnError) {
  VkResultOf<Image> image = create_image(context(), {.layers = limits().maxImageArrayLayers + 1,
                                                     .view = VK_IMAGE_VIEW_TYPE_2D_ARRAY});
  ASSERT_FALSE(image);
  EXPECT_NE(image.error().message.find("maxImageArrayLayers"), std::string::npos) << image.error().message;
}

}  // namespace
}  // namespace facet::runtime
