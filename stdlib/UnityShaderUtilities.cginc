// UnityObjectToClipPos and its float4 overload.
#ifndef UNITY_SHADER_UTILITIES_INCLUDED
#define UNITY_SHADER_UTILITIES_INCLUDED

#include "UnityShaderVariables.cginc"
#include "FacetCore.hlsl"

inline float4 UnityObjectToClipPos(in float3 pos) { return FacetObjectToClipPos(pos); }
// Code written for Unity passes the float4 vertex position; w is taken as 1.
inline float4 UnityObjectToClipPos(float4 pos) { return FacetObjectToClipPos(pos.xyz); }

#endif // UNITY_SHADER_UTILITIES_INCLUDED
