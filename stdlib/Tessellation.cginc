// Tessellation-factor helpers for hull-shader patch constant functions
// (and surface shaders' tessellate:). Factors are (edge 0, edge 1, edge 2,
// inside) for a triangle; edge i is opposite vertex i.
#ifndef TESSELLATION_CGINC_INCLUDED
#define TESSELLATION_CGINC_INCLUDED

#include "UnityShaderVariables.cginc"

// `tess` up to minDist from the camera, falling linearly to 1% of it at maxDist.
float UnityCalcDistanceTessFactor(float4 vertex, float minDist, float maxDist, float tess)
{
    float dist = distance(mul(unity_ObjectToWorld, vertex).xyz, _WorldSpaceCameraPos);
    return clamp(1.0 - (dist - minDist) / (maxDist - minDist), 0.01, 1.0) * tess;
}

// Per-vertex factors to edge factors (mean of the edge's two vertices) and
// the inside factor (mean of all three).
float4 UnityCalcTriEdgeTessFactors(float3 triVertexFactors)
{
    float3 f = triVertexFactors;
    return float4(0.5 * (f.y + f.z), 0.5 * (f.x + f.z), 0.5 * (f.x + f.y), (f.x + f.y + f.z) / 3.0);
}

// Enough segments that an edge spans about edgeLen pixels (ignoring the
// field of view: the world length over the distance, times screen height).
float UnityCalcEdgeTessFactor(float3 wpos0, float3 wpos1, float edgeLen)
{
    float dist = distance(0.5 * (wpos0 + wpos1), _WorldSpaceCameraPos);
    return max(distance(wpos0, wpos1) * _ScreenParams.y / (edgeLen * dist), 1.0);
}

float UnityDistanceFromPlane(float3 pos, float4 plane) { return dot(float4(pos, 1.0), plane); }

// True when all three points lie more than cullEps outside one of the
// left/right/bottom/top planes (unity_CameraWorldClipPlanes; all-zero planes
// cull nothing).
bool UnityWorldViewFrustumCull(float3 wpos0, float3 wpos1, float3 wpos2, float cullEps)
{
    for (int p = 0; p < 4; ++p) {
        float4 plane = unity_CameraWorldClipPlanes[p];
        if (UnityDistanceFromPlane(wpos0, plane) < -cullEps && UnityDistanceFromPlane(wpos1, plane) < -cullEps &&
            UnityDistanceFromPlane(wpos2, plane) < -cullEps)
            return true;
    }
    return false;
}

float4 UnityDistanceBasedTess(float4 v0, float4 v1, float4 v2, float minDist, float maxDist, float tess)
{
    return UnityCalcTriEdgeTessFactors(float3(UnityCalcDistanceTessFactor(v0, minDist, maxDist, tess),
                                              UnityCalcDistanceTessFactor(v1, minDist, maxDist, tess),
                                              UnityCalcDistanceTessFactor(v2, minDist, maxDist, tess)));
}

float4 UnityEdgeLengthBasedTess(float4 v0, float4 v1, float4 v2, float edgeLength)
{
    float3 p0 = mul(unity_ObjectToWorld, v0).xyz;
    float3 p1 = mul(unity_ObjectToWorld, v1).xyz;
    float3 p2 = mul(unity_ObjectToWorld, v2).xyz;
    float3 e = float3(UnityCalcEdgeTessFactor(p1, p2, edgeLength), UnityCalcEdgeTessFactor(p2, p0, edgeLength),
                      UnityCalcEdgeTessFactor(p0, p1, edgeLength));
    return float4(e, (e.x + e.y + e.z) / 3.0);
}

// The same, with factors 0 (patch dropped) for patches outside the view by
// more than maxDisplacement.
float4 UnityEdgeLengthBasedTessCull(float4 v0, float4 v1, float4 v2, float edgeLength, float maxDisplacement)
{
    float3 p0 = mul(unity_ObjectToWorld, v0).xyz;
    float3 p1 = mul(unity_ObjectToWorld, v1).xyz;
    float3 p2 = mul(unity_ObjectToWorld, v2).xyz;
    if (UnityWorldViewFrustumCull(p0, p1, p2, maxDisplacement)) return float4(0, 0, 0, 0);
    return UnityEdgeLengthBasedTess(v0, v1, v2, edgeLength);
}

#endif // TESSELLATION_CGINC_INCLUDED
