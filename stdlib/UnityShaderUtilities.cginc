// UnityObjectToClipPos and its float4 overload.
#ifndef UNITY_SHADER_UTILITIES_INCLUDED
#define UNITY_SHADER_UTILITIES_INCLUDED

#include "UnityShaderVariables.cginc"
#include "FacetCore.hlsl"

inline float4 UnityObjectToClipPos(in float3 pos) { return FacetObjectToClipPos(pos); }
// Code written for Unity passes the float4 vertex position; w is taken as 1.
inline float4 UnityObjectToClipPos(float4 pos) { return FacetObjectToClipPos(pos.xyz); }

// Omni-directional stereo: the eye sits on a circle of radius `ipd` (half
// the eye separation) around the camera, looking along the circle's tangent
// through worldPos; the offset moves the point so that a camera at the
// centre sees it as that eye would. Zero straight up/down.
float3 ODSOffset(float3 worldPos, float ipd)
{
    float3 toPoint = worldPos - _WorldSpaceCameraPos.xyz;
    float dist = sqrt(max(dot(toPoint, toPoint), 2.4414e-4));
    float3 dir = toPoint / dist;
    float3 side = cross(dir, float3(0.0, 1.0, 0.0));
    if (dot(side, side) < 2.4414e-4) return float3(0, 0, 0);
    side = normalize(side);
    float along = ipd * ipd / dist;
    float across = ipd / dist * sqrt(max(dist * dist - ipd * ipd, 2.4414e-4));
    return side * across - dir * along;
}
// Clip position with the ODS offset under STEREO_CUBEMAP_RENDER_ON (the half
// separation is 0 in facet, so it is UnityObjectToClipPos).
inline float4 UnityObjectToClipPosODS(float3 pos)
{
    float3 posWorld = FacetObjectToWorldPos(pos);
#if defined(STEREO_CUBEMAP_RENDER_ON)
    posWorld += ODSOffset(posWorld, unity_HalfStereoSeparation.x);
#endif
    return FacetWorldToClipPos(posWorld);
}
inline float4 UnityObjectToClipPosODS(float4 pos) { return UnityObjectToClipPosODS(pos.xyz); }

#endif // UNITY_SHADER_UTILITIES_INCLUDED
