// A progress bar on a terminal for long builds: "[=====>     ] 812/2052
// programs", redrawn at most ten times a second and cleared at the end.
// Nothing at all when standard error is not a terminal.
#pragma once

#include <chrono>
#include <cstdint>
#include <ostream>
#include <string>

namespace facet::tools {

class ProgressBar {
 public:
  ProgressBar(std::ostream& out, bool enabled) : out_(out), enabled_(enabled) {}
  ~ProgressBar() { finish(); }

  void update(uint64_t done, uint64_t total);
  void finish();

 private:
  std::ostream& out_;
  bool enabled_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point last_{};
};

}  // namespace facet::tools
