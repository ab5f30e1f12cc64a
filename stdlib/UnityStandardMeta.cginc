// The Standard shader's Meta pass: vert_meta/frag_meta give the lightmapper
// the surface's albedo (diffuse plus a roughness-weighted share of the
// specular colour) and emission (UnityMetaPass.cginc).
#ifndef UNITY_STANDARD_META_INCLUDED
#define UNITY_STANDARD_META_INCLUDED

#ifndef UNITY_PASS_META
#define UNITY_PASS_META 1
#endif

#include "UnityCG.cginc"
#include "UnityStandardInput.cginc"
#include "UnityMetaPass.cginc"
#include "UnityStandardCore.cginc"

struct v2f_meta
{
    float4 pos : SV_POSITION;
    float4 uv : TEXCOORD0;
};

v2f_meta vert_meta(VertexInput v)
{
    v2f_meta o;
    o.pos = UnityMetaVertexPosition(v.vertex, v.uv1.xy, v.uv2.xy, unity_LightmapST, unity_DynamicLightmapST);
    o.uv = TexCoords(v);
    return o;
}

// Rough specular surfaces scatter part of their specular colour like
// diffuse: albedo + specular * roughness / 2.
half3 UnityLightmappingAlbedo(half3 diffuse, half3 specular, half smoothness)
{
    half roughness = SmoothnessToRoughness(smoothness);
    return diffuse + specular * roughness * 0.5;
}

float4 frag_meta(v2f_meta i) : SV_Target
{
    FragmentCommonData data = UNITY_SETUP_BRDF_INPUT(i.uv);
    UnityMetaInput o;
    UNITY_INITIALIZE_OUTPUT(UnityMetaInput, o);
    o.Albedo = UnityLightmappingAlbedo(data.diffColor, data.specColor, data.smoothness);
    o.SpecularColor = data.specColor;
    o.Emission = Emission(i.uv.xy);
    return UnityMetaFragment(o);
}

#endif // UNITY_STANDARD_META_INCLUDED
