// Runs glslang and SPIRV-Tools work on a thread of its own, with a large
// stack and a wall-time budget.
//
// glslang parses (HLSL), preprocesses (#if expressions) and walks its AST
// recursively; deep but legitimate code (long generated expressions) needs
// more than the 8 MiB a main thread usually gets, and far more than a
// worker thread's default. The worker's stack is reserved, not committed:
// only the pages recursion touches cost memory.
//
// glslang cannot be interrupted. When the work outlives its time budget the
// caller cannot get it back or free what it holds, and leaving it running
// while the process goes on (or exits and runs glslang's FinalizeProcess
// under it) is not safe. So the waiting thread prints the located error it
// is given and ends the process with exit code 1 (_exit: no destructors,
// no buffered output). Nothing half-written is left: outputs are written
// only after every compile has finished.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>

namespace facet::backend {

// The worker's stack. 512 MiB of address space; a 100,000-deep HLSL
// expression uses well under a tenth of it.
inline constexpr size_t kWorkerStackBytes = size_t(512) << 20;

// The default of BackendOptions::time_limit_s.
inline constexpr uint32_t kDefaultTimeLimitSeconds = 60;

// Runs `work` on a thread with a kWorkerStackBytes stack and waits for it.
// With `time_limit_s` > 0, when `work` has not returned after that many
// seconds, writes `timeout_message()` to standard error and calls _exit(1).
// When no such thread can be created, `work` runs on the calling thread.
void run_on_worker(const std::function<void()>& work, uint32_t time_limit_s,
                   const std::function<std::string()>& timeout_message);

}  // namespace facet::backend
