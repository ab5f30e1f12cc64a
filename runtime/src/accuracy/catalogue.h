// The rows of the accuracy study: what each approximation is compared with,
// how its error is computed on the CPU twins, and the HLSL that evaluates it
// once on the GPU from eight varying inputs p0..p7 in [0.05, 1].
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "facet/runtime/accuracy.h"

namespace facet::runtime::accuracy {

struct RowSpec {
  StudyRow row;  // id, group, name, reference, metric, anchor filled
  // Fills row.error and row.detail; empty for rows that are references or
  // have no reference (their error stays 0 and the table says so).
  std::function<void(StudyRow&)> measure;
  std::string includes;  // HLSL include lines
  std::string hlsl;      // statements that set `float value` from p0..p7
};

std::vector<RowSpec> catalogue();

// What the GPU passes evaluate when the model is "nothing": the same loads,
// loop and store around one multiply.
inline constexpr const char* kNullModel = "value = p0 * p1;";

}  // namespace facet::runtime::accuracy
