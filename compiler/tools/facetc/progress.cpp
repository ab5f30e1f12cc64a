#include "progress.h"

#include <fmt/format.h>

namespace facet::tools {

void ProgressBar::update(uint64_t done, uint64_t total) {
  if (!enabled_ || total == 0) return;
  auto now = std::chrono::steady_clock::now();
  if (drawn_ && done < total && now - last_ < std::chrono::milliseconds(100)) return;
  last_ = now;
  constexpr int kWidth = 30;
  int filled = int(kWidth * done / total);
  std::string bar(size_t(filled), '=');
  if (filled < kWidth) bar += '>';
  bar.resize(kWidth, ' ');
  out_ << fmt::format("\r[{}] {}/{} programs", bar, done, total) << std::flush;
  drawn_ = true;
}

void ProgressBar::finish() {
  if (!drawn_) return;
  out_ << "\r" << std::string(60, ' ') << "\r" << std::flush;
  drawn_ = false;
}

}  // namespace facet::tools
