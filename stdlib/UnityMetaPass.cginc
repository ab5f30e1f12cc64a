// The Meta pass's interface (what a lightmapper reads): albedo or emission
// of the surface rendered in lightmap-UV space. facet has no lightmapper;
// the uniforms below are loose ("$Globals") and the runtime may fill them by
// name: unity_MetaVertexControl.x = 1 lays the mesh out by its UV1 (with
// unity_LightmapST), .y by UV2 (unity_DynamicLightmapST); otherwise the mesh
// is drawn normally. unity_MetaFragmentControl.x = 1 outputs albedo, .y
// emission (else black).
#ifndef UNITY_META_PASS_INCLUDED
#define UNITY_META_PASS_INCLUDED

#include "UnityCG.cginc"

float4 unity_MetaVertexControl;
float4 unity_MetaFragmentControl;
// unity_LightmapST and unity_DynamicLightmapST: FacetBuiltins.hlsl (set 3).

struct UnityMetaInput
{
    half3 Albedo;
    half3 Emission;
    half3 SpecularColor;
};

// Clip position of a vertex placed at its lightmap UV (0..1 -> -1..1, v
// down as in Vulkan), or the ordinary clip position.
float4 UnityMetaVertexPosition(float4 vertex, float2 uv1, float2 uv2, float4 lightmapST, float4 dynlightmapST)
{
    if (unity_MetaVertexControl.x > 0) {
        float2 uv = uv1 * lightmapST.xy + lightmapST.zw;
        return float4(uv * 2.0 - 1.0, 0.5, 1.0);
    }
    if (unity_MetaVertexControl.y > 0) {
        float2 uv = uv2 * dynlightmapST.xy + dynlightmapST.zw;
        return float4(uv * 2.0 - 1.0, 0.5, 1.0);
    }
    return UnityObjectToClipPos(vertex);
}

half4 UnityMetaFragment(UnityMetaInput metaIn)
{
    half4 res = 0;
    if (unity_MetaFragmentControl.x > 0) res = half4(saturate(metaIn.Albedo), 1);
    if (unity_MetaFragmentControl.y > 0) res = half4(metaIn.Emission, 1);
    return res;
}

#endif // UNITY_META_PASS_INCLUDED
