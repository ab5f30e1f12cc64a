#include "include_scan.h"

#include <functional>
#include <string_view>

namespace facet::backend {

std::shared_ptr<const ScannedText> scan_text(std::string text) {
  auto scanned = std::make_shared<ScannedText>();
  scanned->text = std::move(text);  // tokens view the text in its final place
  scanned->hazard = find_recursion_hazard(scanned->text);
  if (!scanned->hazard) scanned->lines = MacroBudget::tokenize(scanned->text);
  return scanned;
}

std::shared_ptr<const ScannedText> IncludeScanCache::scan(std::string text) {
  const size_t hash = std::hash<std::string_view>{}(text);
  {
    std::lock_guard lock(mutex_);
    if (auto it = by_hash_.find(hash); it != by_hash_.end()) {
      for (const std::shared_ptr<const ScannedText>& s : it->second) {
        if (s->text == text) return s;
      }
    }
  }
  // Scanned outside the lock: two threads may scan one text at once, and
  // the second keeps the first's.
  std::shared_ptr<const ScannedText> scanned = scan_text(std::move(text));
  std::lock_guard lock(mutex_);
  std::vector<std::shared_ptr<const ScannedText>>& same_hash = by_hash_[hash];
  for (const std::shared_ptr<const ScannedText>& s : same_hash) {
    if (s->text == scanned->text) return s;
  }
  if (bytes_ + scanned->text.size() <= kMaxBytes) {
    bytes_ += scanned->text.size();
    same_hash.push_back(scanned);
  }
  return scanned;
}

size_t IncludeScanCache::size() const {
  std::lock_guard lock(mutex_);
  size_t n = 0;
  for (const auto& [hash, texts] : by_hash_) n += texts.size();
  return n;
}

}  // namespace facet::backend
