// The scans every included text gets before glslang reads it (the
// recursion-hazard check and the macro budget's tokens) depend on the text
// alone, and a build includes the same stdlib files into every stage program
// of every variant: a Backend keeps each text's scan, once, for all of them.
#pragma once

#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "macro_budget.h"
#include "source_assembly.h"

namespace facet::backend {

struct ScannedText {
  std::string text;
  MacroBudget::TokenLines lines;  // views into `text`
  std::optional<RecursionHazard> hazard;
};

// `text` scanned now, not kept.
std::shared_ptr<const ScannedText> scan_text(std::string text);

// Thread-safe. Holds at most kMaxBytes of text; past that, texts are scanned
// and not kept (a build's includes are far smaller).
class IncludeScanCache {
 public:
  static constexpr uint64_t kMaxBytes = uint64_t(256) << 20;

  std::shared_ptr<const ScannedText> scan(std::string text);
  size_t size() const;

 private:
  mutable std::mutex mutex_;
  std::unordered_map<size_t, std::vector<std::shared_ptr<const ScannedText>>> by_hash_;
  uint64_t bytes_ = 0;
};

}  // namespace facet::backend
