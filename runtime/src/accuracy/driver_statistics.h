// The study's driver-statistics columns (VK_KHR_pipeline_executable_properties):
// measured on the device (driver_statistics.cpp), written to and read from
// the study's JSON and shown in its page (driver_report.cpp). Kept apart
// from the other columns so that each part of the study reads on its own.
#pragma once

#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "accuracy/catalogue.h"
#include "facet/diagnostics.h"
#include "facet/result.h"
#include "facet/runtime/accuracy.h"
#include "facet/runtime/compute.h"

namespace facet::runtime::accuracy {

// The one-evaluation compute kernel of a row (inputs from a buffer, the value
// to a buffer) whose SPIR-V instructions the study counts (study.cpp).
std::string single_kernel(const std::string& includes, const std::string& hlsl);

// A row's single_kernel as a compute pipeline (two storage buffers, entry
// "main"), created with VK_PIPELINE_CREATE_CAPTURE_STATISTICS_BIT_KHR when
// `capture` (which needs context.pipeline_statistics()).
Result<ComputePipeline> kernel_pipeline(const Context& context, const std::string& includes, const std::string& hlsl,
                                        bool capture, Diagnostics& diags);

// Records whether `context` has pipeline statistics on and, where it has,
// fills every row's driver_* fields from its single_kernel, created with
// VK_PIPELINE_CREATE_CAPTURE_STATISTICS_BIT_KHR; instructions and code bytes
// minus those of the null model's kernel. Errors are diagnostics.
Result<void> measure_driver_statistics(const Context& context, const std::vector<RowSpec>& specs, Study& study,
                                       Diagnostics& diags);

// The row's driver_* fields into its JSON object, only those it has, and back
// (absent keys leave them empty: older studies read unchanged).
void write_driver_fields(const StudyRow& row, nlohmann::ordered_json& j);
void read_driver_fields(const nlohmann::json& j, StudyRow& row);

// The table's driver columns: a column only where some row has its value, a
// row without it shows "—".
std::string driver_header_cells(const Study& study);
std::string driver_row_cells(const Study& study, const StudyRow& row);
// What the page says about driver statistics: which names were read, or that
// the device does not offer them.
std::string driver_statistics_html(const Study& study);
// The raw statistics of every row, folded away under a summary; "" when no
// row has any.
std::string driver_raw_statistics_html(const Study& study);

}  // namespace facet::runtime::accuracy
