// Inputs fuzz_cache found (docs/reliability.md, "Fuzzing"), kept as tests
// of the cache entry decoder. Run under UBSan (scripts/test.sh) they fail
// without their fixes.
#include <gtest/gtest.h>

#include "facet/cache.h"

namespace facet::cache {
namespace {

// An entry whose SPIR-V word count is 0: the decoder copied 0 bytes into the
// empty vector's data(), a null pointer, which memcpy may not be given.
TEST(CacheEntryFuzzRegressionTest, DecodesAnEntryWithNoSpirvWords) {
  const std::string key = "fuzz0000000000000000000000000000";
  CacheEntry entry{{.included_files = {"Example.shader"}}, /*token_hash=*/0x0123456789abcdefull};
  auto decoded = decode_entry(encode_entry(key, entry), key);
  ASSERT_TRUE(decoded) << decoded.error().reason;
  EXPECT_TRUE(decoded->spirv.empty());
  EXPECT_EQ(decoded->included_files, entry.included_files);
  EXPECT_EQ(decoded->token_hash, entry.token_hash);
}

}  // namespace
}  // namespace facet::cache
