// A lavapipe context with validation on, shared by the tests of one suite;
// every test ends by asserting that the validation layer said nothing.
#pragma once

#include <dlfcn.h>
#include <gtest/gtest.h>

#include <memory>

#include "facet/runtime/vulkan_context.h"

namespace facet::runtime::test_support {

// LeakSanitizer checks at exit, after the Vulkan loader has dlclose()d
// lavapipe. Mesa 22.3's lavapipe makes a once-per-load allocation while
// physical devices are enumerated and keeps it in a global of its own; once
// the library is unmapped that pointer is gone and LSan reports the block as
// leaked, with no module name to suppress it by (a bare C program creating
// and destroying one instance shows the same 128 bytes). Keeping the driver
// mapped (RTLD_NODELETE) leaves the block reachable, as it really is; where
// the library is absent this does nothing.
inline const bool kLavapipePinned = dlopen("libvulkan_lvp.so", RTLD_NOW | RTLD_NODELETE) != nullptr;

class LavapipeTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    VkResultOf<std::unique_ptr<Context>> created = create_context({.validation = true});
    ASSERT_TRUE(created) << describe(created.error());
    context_ = std::move(*created);
  }
  static void TearDownTestSuite() { context_.reset(); }
  void SetUp() override { ASSERT_NE(context_, nullptr) << "no lavapipe context (see the suite's setup failure)"; }
  void TearDown() override {
    if (!context_) return;
    EXPECT_TRUE(context_->messages().empty()) << context_->messages_text();
    context_->clear_messages();
  }
  static Context& context() { return *context_; }

 private:
  inline static std::unique_ptr<Context> context_;
};

}  // namespace facet::runtime::test_support
