// The error budget of every approximation the accuracy study measures: the
// largest error (in the row's own metric, over the domain the metric names)
// the stdlib's form may have. docs/accuracy.md lists them; a test holds every
// row to its budget, so that making an approximation worse fails.
#pragma once

#include <optional>
#include <string_view>

namespace facet::runtime::accuracy {

// nullopt: a reference row (no error), or a row that shows a failure on
// purpose (D_GGX_fp16, which overflows by design).
std::optional<double> error_budget(std::string_view row_id);

}  // namespace facet::runtime::accuracy
