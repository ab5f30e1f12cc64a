// Templated twins of the GGX D, V and F terms of stdlib/FacetBRDF.hlsl, to be
// run in GCC's _Float16 (true IEEE half arithmetic: every + - * / and sqrt
// rounds to half) and, for comparison, in float and double. They predict what
// a real half-precision ALU does with each form (docs/stability.md, "fp16");
// a GPU that keeps RelaxedPrecision at fp32 (lavapipe) does not show it.
//
// The operations are written in the HLSL order, so that rounding and overflow
// happen where they would in a shader compiled for half: `k * k * kInvPi` is
// (k * k) * kInvPi, as HLSL parses it.
#pragma once

#include <cmath>

namespace facet::reference::fp16 {

#if defined(__FLT16_MAX__)
using half = _Float16;
inline constexpr bool kHasHalf = true;
#else
using half = float;  // no _Float16 on this compiler: the fp16 tests skip
inline constexpr bool kHasHalf = false;
#endif

template <class T>
inline T sqrt_t(T x) {
  // Rounded back to T: the square root of a half is correctly rounded in half
  // when computed in float (24 >= 2*11 + 2 bits), as a half ALU would return.
  return T(std::sqrt(float(x)));
}

template <class T>
struct Vec3 {
  T x, y, z;
};
template <class T>
inline T dot(const Vec3<T>& a, const Vec3<T>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <class T>
inline Vec3<T> cross(const Vec3<T>& a, const Vec3<T>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

template <class T>
inline constexpr T kInvPi = T(0.31830988618379067154);
template <class T>
inline constexpr T kPi = T(3.14159265358979323846);

// FacetD_GGX: 1 - NoH^2 (1 - alpha^2) by two multiply-adds.
template <class T>
inline T D_GGX(T NoH, T alpha) {
  T a2 = alpha * alpha;
  T d = (NoH * a2 - NoH) * NoH + T(1);
  return a2 / (kPi<T> * d * d);
}

// FacetD_GGX_FP16Safe as the stdlib wrote it before the fix: |n x h|^2 and
// k <= 453.5, then k * k * (1/pi), whose k^2 overflows half for k > 256.
template <class T>
inline T D_GGX_FP16SafeUnassociated(const Vec3<T>& n, const Vec3<T>& h, T alpha) {
  Vec3<T> nxh = cross(n, h);
  T oneMinusNoH2 = dot(nxh, nxh);
  T a = dot(n, h) * alpha;
  T k = alpha / (oneMinusNoH2 + a * a);
  if (k > T(453.5)) k = T(453.5);
  return k * k * kInvPi<T>;
}

// FacetD_GGX_FP16Safe as the stdlib writes it: the last product associated
// as k * (k * (1/pi)), which keeps every intermediate below 65 504 when
// k <= 453.5 (453.5^2 = 205 662 alone does not fit in half).
template <class T>
inline T D_GGX_FP16Safe(const Vec3<T>& n, const Vec3<T>& h, T alpha) {
  Vec3<T> nxh = cross(n, h);
  T oneMinusNoH2 = dot(nxh, nxh);
  T a = dot(n, h) * alpha;
  T k = alpha / (oneMinusNoH2 + a * a);
  if (k > T(453.5)) k = T(453.5);
  return k * (k * kInvPi<T>);
}

// FacetV_SmithGGXCorrelated.
template <class T>
inline T V_SmithGGXCorrelated(T NoV, T NoL, T alpha) {
  T a2 = alpha * alpha;
  T lambdaV = NoL * sqrt_t((NoV - a2 * NoV) * NoV + a2);
  T lambdaL = NoV * sqrt_t((NoL - a2 * NoL) * NoL + a2);
  return T(0.5) / (lambdaV + lambdaL);
}

// FacetV_SmithGGXCorrelatedFast (Hammon): 0.5 / lerp(2 NoL NoV, NoL + NoV, alpha),
// HLSL's lerp(a, b, t) = a + t (b - a).
template <class T>
inline T V_SmithGGXCorrelatedFast(T NoV, T NoL, T alpha) {
  T a = T(2) * NoL * NoV;
  T b = NoL + NoV;
  return T(0.5) / (a + alpha * (b - a));
}

// FacetF_Schlick (scalar f0) with FacetPow5.
template <class T>
inline T F_Schlick(T f0, T f90, T VoH) {
  T x = T(1) - VoH;
  T x2 = x * x;
  return f0 + (f90 - f0) * (x2 * x2 * x);
}

}  // namespace facet::reference::fp16
