// Half-precision overloads of the HLSL intrinsics, for kernels compiled with
// 16-bit types (facetc's compute kernels with BackendOptions::hlsl_16bit_types,
// which defines FACET_16BIT_TYPES). glslang's HLSL intrinsics take and return
// 32-bit floats only: sqrt(half) converts its argument to float and returns a
// float, which then does not convert back to half implicitly. These overloads
// take and return half, so code written for float and rewritten for half
// (backend::to_half_precision) compiles; each intrinsic is evaluated in fp32
// and rounded to half once, while the arithmetic around it (+ - * /) is real
// 16-bit arithmetic. docs/stability.md ("fp16") says where this matters.
#ifndef FACET_HALF_INCLUDED
#define FACET_HALF_INCLUDED

// Without 16-bit types half is float, the intrinsics already take it, and
// the file defines nothing (so a shader that includes it compiles both ways).
#ifdef FACET_16BIT_TYPES

#define FACET_HALF_1(fn, H, F) H fn(H a) { return (H)fn((F)a); }
#define FACET_HALF_2(fn, H, F) H fn(H a, H b) { return (H)fn((F)a, (F)b); }
#define FACET_HALF_3(fn, H, F) H fn(H a, H b, H c) { return (H)fn((F)a, (F)b, (F)c); }
#define FACET_HALF_ALL(H, F)                                                                        \
    FACET_HALF_1(sqrt, H, F) FACET_HALF_1(rsqrt, H, F) FACET_HALF_1(rcp, H, F)                      \
    FACET_HALF_1(saturate, H, F) FACET_HALF_1(abs, H, F) FACET_HALF_1(frac, H, F)                   \
    FACET_HALF_1(floor, H, F) FACET_HALF_1(ceil, H, F)                                              \
    FACET_HALF_1(sin, H, F) FACET_HALF_1(cos, H, F) FACET_HALF_1(tan, H, F)                         \
    FACET_HALF_1(asin, H, F) FACET_HALF_1(acos, H, F) FACET_HALF_1(atan, H, F)                      \
    FACET_HALF_1(exp, H, F) FACET_HALF_1(exp2, H, F) FACET_HALF_1(log, H, F) FACET_HALF_1(log2, H, F) \
    FACET_HALF_2(min, H, F) FACET_HALF_2(max, H, F) FACET_HALF_2(pow, H, F) FACET_HALF_2(step, H, F) \
    FACET_HALF_2(atan2, H, F) FACET_HALF_2(fmod, H, F)                                              \
    FACET_HALF_3(lerp, H, F) FACET_HALF_3(clamp, H, F) FACET_HALF_3(smoothstep, H, F) FACET_HALF_3(mad, H, F)
#define FACET_HALF_VECTOR(H, F)                                                                     \
    FACET_HALF_1(normalize, H, F) FACET_HALF_2(reflect, H, F)                                       \
    half dot(H a, H b) { return (half)dot((F)a, (F)b); }                                            \
    half length(H a) { return (half)length((F)a); }                                                 \
    half distance(H a, H b) { return (half)distance((F)a, (F)b); }

FACET_HALF_ALL(half, float)
FACET_HALF_ALL(half2, float2)
FACET_HALF_ALL(half3, float3)
FACET_HALF_ALL(half4, float4)
FACET_HALF_VECTOR(half2, float2)
FACET_HALF_VECTOR(half3, float3)
FACET_HALF_VECTOR(half4, float4)
half3 cross(half3 a, half3 b) { return (half3)cross((float3)a, (float3)b); }

#undef FACET_HALF_1
#undef FACET_HALF_2
#undef FACET_HALF_3
#undef FACET_HALF_ALL
#undef FACET_HALF_VECTOR

#endif  // FACET_16BIT_TYPES
#endif  // FACET_HALF_INCLUDED
