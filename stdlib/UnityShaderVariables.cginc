// Unity's built-in shader variables: the uniforms of FacetBuiltins.hlsl plus
// the UNITY_MATRIX_* names. Included implicitly by CGPROGRAM.
#ifndef UNITY_SHADER_VARIABLES_INCLUDED
#define UNITY_SHADER_VARIABLES_INCLUDED

#include "HLSLSupport.cginc"
#include "FacetBuiltins.hlsl"

#define UNITY_MATRIX_M unity_ObjectToWorld
#define UNITY_MATRIX_I_M unity_WorldToObject
#define UNITY_MATRIX_V unity_MatrixV
#define UNITY_MATRIX_I_V unity_MatrixInvV
#define UNITY_MATRIX_P unity_MatrixP
#define UNITY_MATRIX_VP unity_MatrixVP
#define UNITY_MATRIX_MV mul(unity_MatrixV, unity_ObjectToWorld)
#define UNITY_MATRIX_T_MV transpose(UNITY_MATRIX_MV)
#define UNITY_MATRIX_IT_MV transpose(mul(unity_WorldToObject, unity_MatrixInvV))
#define UNITY_MATRIX_MVP mul(unity_MatrixVP, unity_ObjectToWorld)
#define glstate_matrix_projection unity_MatrixP
#define UNITY_LIGHTMODEL_AMBIENT glstate_lightmodel_ambient
#define unity_MatrixMVP UNITY_MATRIX_MVP
#define unity_MatrixMV UNITY_MATRIX_MV
#define unity_MatrixTMV UNITY_MATRIX_T_MV
#define unity_MatrixITMV UNITY_MATRIX_IT_MV
#define glstate_matrix_transpose_modelview0 UNITY_MATRIX_T_MV
// Fixed-function texture matrices are identity.
#define UNITY_MATRIX_TEXTURE0 float4x4(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1)
#define UNITY_MATRIX_TEXTURE1 UNITY_MATRIX_TEXTURE0
#define UNITY_MATRIX_TEXTURE2 UNITY_MATRIX_TEXTURE0
#define UNITY_MATRIX_TEXTURE3 UNITY_MATRIX_TEXTURE0

#if defined(DIRECTIONAL_COOKIE) || defined(DIRECTIONAL)
#define USING_DIRECTIONAL_LIGHT
#endif

// Stereo: facet renders one eye per pass, so the eye index is 0, the
// per-eye screen scale/offset is identity and the omni-directional-stereo
// half separation is 0 (UNITY_SINGLE_PASS_STEREO and friends do nothing).
static const int unity_StereoEyeIndex = 0;
static const float4 unity_StereoScaleOffset[2] = { float4(1, 1, 0, 0), float4(1, 1, 0, 0) };
static const float4 unity_HalfStereoSeparation = float4(0, 0, 0, 0);

// Light probe proxy volumes are not supported (unity_ProbeVolume* exist in
// FacetBuiltins.hlsl, zero).
#ifdef UNITY_LIGHT_PROBE_PROXY_VOLUME
#undef UNITY_LIGHT_PROBE_PROXY_VOLUME
#endif
#define UNITY_LIGHT_PROBE_PROXY_VOLUME 0

#include "UnityInstancing.cginc"

#endif // UNITY_SHADER_VARIABLES_INCLUDED
