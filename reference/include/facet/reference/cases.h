// The case table: every stdlib lighting function at its parameter settings, with the
// deterministic input points to evaluate it on and the CPU twin that says what it must
// return. The GPU evaluator (fp32 shader on lavapipe) and the CPU property tests share it.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace facet::reference {

// One shader function at one parameter setting, to be evaluated on many input points
// by the CPU twin (double) and by the shader (fp32, GPU compute) and compared.
struct FunctionCase {
  std::string function;            // the HLSL name == the C++ twin name, e.g. "FacetD_GGX"
  std::string setting;             // the parameter setting, e.g. "alpha=0.25"
  int input_count = 0;             // floats per input point, 1..16
  int output_count = 1;            // floats per result, 1..4
  std::string includes;            // HLSL include lines, e.g. "#include \"FacetBRDF.hlsl\"\n"
  std::string hlsl;                // HLSL statements that read `float x[16]` (the point) and assign `float4 r`
  std::function<void(const double* x, double* r)> reference;   // CPU twin on the same point (x already rounded to float)
  std::function<void(uint32_t i, uint32_t n, float* x)> sample; // point i of n, deterministic (seeded), input_count floats
  double relative_tolerance = 1e-4;  // |gpu - cpu| <= relative_tolerance * |cpu| + absolute_floor
  double absolute_floor = 1e-6;      // "where the value is not tiny"
};

std::vector<FunctionCase> facet_model_cases();      // A: facet's lighting library (reference/cases/facet_cases.cpp)
std::vector<FunctionCase> unity_standard_cases();   // C: Unity-named functions, BRDF1/2/3 etc. (reference/cases/unity_cases.cpp)
// B: each row of the lighting-model table with HLSL (facet/reference/models.h), the
// whole model against its twin (reference/cases/model_cases.cpp).
std::vector<FunctionCase> lighting_model_cases();
std::vector<FunctionCase> lighting_cases();         // A, C and B, concatenated (reference/cases/cases.cpp)

}  // namespace facet::reference
