// The study's fp16 columns (docs/accuracy.md, "The fp16 columns"): which rows
// also run in real 16-bit arithmetic on the GPU, over which inputs, against
// which fp64 twin. The row's own HLSL (RowSpec::hlsl) is what runs, rewritten
// for half by backend::to_half_precision, with FacetHalf.hlsl and the stdlib
// rewritten the same way.
#pragma once

#include <array>
#include <functional>
#include <string>
#include <vector>

namespace facet::runtime::accuracy {

// One point of a row's inputs p0..p7.
using Inputs = std::array<double, 8>;

struct Fp16Row {
  std::string id;      // the study row (RowSpec::row.id)
  std::string domain;  // the inputs, in words (StudyRow::fp16_domain)
  std::vector<Inputs> points;                // the domain's points (float-representable)
  std::function<double(const Inputs&)> twin;  // the row's CPU twin in fp64
  // The error kernel's statements (setting `value` from p0..p7, written for
  // float) when they are not the row's own; the timed kernel is always the row's.
  std::string hlsl;
};

// In catalogue order. Each point's inputs are rounded to float, the buffer's
// type, and the twin is evaluated at those float values; the kernel rounds
// them to half, so the error includes that rounding, as a half shader's does.
std::vector<Fp16Row> fp16_rows();

// The largest |gpu / twin - 1| over the points; infinity when a GPU value is
// not finite (half overflow, or 0/0).
double max_relative_error(const std::vector<float>& gpu, const Fp16Row& row);

}  // namespace facet::runtime::accuracy
