// The Standard shader's material inputs: its uniforms (named as the
// Standard shader's Properties), the vertex input, and the functions that
// read albedo, alpha, occlusion, specular/metallic + smoothness, emission,
// the tangent-space normal and the parallax offset from them, following the
// material keywords (_NORMALMAP, _DETAIL_MULX2, _METALLICGLOSSMAP,
// _SPECGLOSSMAP, _SMOOTHNESS_TEXTURE_ALBEDO_CHANNEL_A, _EMISSION,
// _PARALLAXMAP). Every texture is declared whatever the keywords, so that the
// material-set bindings are the same in every variant and stage.
#ifndef UNITY_STANDARD_INPUT_INCLUDED
#define UNITY_STANDARD_INPUT_INCLUDED

#include "UnityCG.cginc"
#include "UnityStandardConfig.cginc"
#include "UnityPBSLighting.cginc"
#include "UnityStandardUtils.cginc"

// --- Material properties, grouped by what they feed -----------------------

// Base colour and transparency.
half4 _Color;
sampler2D _MainTex;
float4 _MainTex_ST;
half _Cutoff;

// Reflectance and smoothness (metallic or specular setup).
half _Metallic;
sampler2D _MetallicGlossMap;
sampler2D _SpecGlossMap;
float _Glossiness;
float _GlossMapScale;

// Surface detail: normal map, detail layer (on UV0 or UV1), height.
sampler2D _BumpMap;
half _BumpScale;
half _UVSec;
sampler2D _DetailMask;
sampler2D _DetailAlbedoMap;
float4 _DetailAlbedoMap_ST;
sampler2D _DetailNormalMap;
half _DetailNormalMapScale;
sampler2D _ParallaxMap;
half _Parallax;

// Occlusion and emission.
sampler2D _OcclusionMap;
half _OcclusionStrength;
sampler2D _EmissionMap;
half4 _EmissionColor;

// The vertex attributes every Standard pass reads (half is float in facet).
struct VertexInput
{
    float4 vertex : POSITION;
    float3 normal : NORMAL;
    float2 uv0 : TEXCOORD0;
    float2 uv1 : TEXCOORD1;
#if defined(DYNAMICLIGHTMAP_ON) || defined(UNITY_PASS_META)
    float2 uv2 : TEXCOORD2;
#endif
#ifdef _TANGENT_TO_WORLD
    float4 tangent : TANGENT;
#endif
    UNITY_VERTEX_INPUT_INSTANCE_ID
};

// --- facet's helpers --------------------------------------------------------

// Combines the detail albedo with the base one as the _DETAIL_* keyword
// says, weighted by the detail mask; without a mode the base is kept.
half3 FacetStdApplyDetailAlbedo(half3 base, half3 detail, half mask)
{
#if _DETAIL_MULX2
    return base * LerpWhiteTo(detail * unity_ColorSpaceDouble.rgb, mask);
#elif _DETAIL_MUL
    return base * LerpWhiteTo(detail, mask);
#elif _DETAIL_ADD
    return base + detail * mask;
#elif _DETAIL_LERP
    return lerp(base, detail, mask);
#else
    return base;
#endif
}

// Blends the detail normal over the base one: replaced outright in the
// lerp mode, otherwise combined with BlendNormals, as far as the mask goes.
half3 FacetStdApplyDetailNormal(half3 base, half3 detail, half mask)
{
#if _DETAIL_LERP
    half3 target = detail;
#else
    half3 target = BlendNormals(base, detail);
#endif
    return lerp(base, target, mask);
}

// Smoothness where a map is bound: the map's alpha (mapAlpha), unless
// _SMOOTHNESS_TEXTURE_ALBEDO_CHANNEL_A moves it to the albedo's alpha;
// either way scaled by _GlossMapScale.
half FacetStdMapSmoothness(half mapAlpha, float2 uv)
{
#if defined(_SMOOTHNESS_TEXTURE_ALBEDO_CHANNEL_A)
    mapAlpha = tex2D(_MainTex, uv).a;
#endif
    return mapAlpha * _GlossMapScale;
}

// Smoothness without a map: the _Glossiness slider, or the scaled albedo
// alpha when the keyword says smoothness lives there.
half FacetStdSliderSmoothness(float2 uv)
{
#if defined(_SMOOTHNESS_TEXTURE_ALBEDO_CHANNEL_A)
    return tex2D(_MainTex, uv).a * _GlossMapScale;
#else
    return _Glossiness;
#endif
}

// --- The Standard input functions ---------------------------------------

// xy: main UV (tiled by _MainTex_ST); zw: detail UV from UV0 or UV1 (_UVSec),
// tiled by _DetailAlbedoMap_ST.
float4 TexCoords(VertexInput v)
{
    float2 detailSource = (_UVSec == 0) ? v.uv0 : v.uv1;
    return float4(TRANSFORM_TEX(v.uv0, _MainTex), TRANSFORM_TEX(detailSource, _DetailAlbedoMap));
}

half DetailMask(float2 uv) { return tex2D(_DetailMask, uv).a; }

half3 Albedo(float4 texcoords)
{
    half3 base = _Color.rgb * tex2D(_MainTex, texcoords.xy).rgb;
#if _DETAIL
    return FacetStdApplyDetailAlbedo(base, tex2D(_DetailAlbedoMap, texcoords.zw).rgb, DetailMask(texcoords.xy));
#else
    return base;
#endif
}

// With _SMOOTHNESS_TEXTURE_ALBEDO_CHANNEL_A the albedo alpha holds
// smoothness, so only _Color.a is transparency.
half Alpha(float2 uv)
{
    half alpha = _Color.a;
#if !defined(_SMOOTHNESS_TEXTURE_ALBEDO_CHANNEL_A)
    alpha = tex2D(_MainTex, uv).a * alpha;
#endif
    return alpha;
}

half Occlusion(float2 uv) { return LerpOneTo(tex2D(_OcclusionMap, uv).g, _OcclusionStrength); }

// rgb: specular colour, a: smoothness.
half4 SpecularGloss(float2 uv)
{
#ifdef _SPECGLOSSMAP
    half4 texel = tex2D(_SpecGlossMap, uv);
    return half4(texel.rgb, FacetStdMapSmoothness(texel.a, uv));
#else
    return half4(_SpecColor.rgb, FacetStdSliderSmoothness(uv));
#endif
}

// x: metallic, y: smoothness.
half2 MetallicGloss(float2 uv)
{
#ifdef _METALLICGLOSSMAP
    half4 texel = tex2D(_MetallicGlossMap, uv);
    return half2(texel.r, FacetStdMapSmoothness(texel.a, uv));
#else
    return half2(_Metallic, FacetStdSliderSmoothness(uv));
#endif
}

// The roughness setup: x metallic, y smoothness = 1 - roughness, the
// roughness from _SpecGlossMap.r (with _SPECGLOSSMAP) or _Glossiness.
half2 MetallicRough(float2 uv)
{
#ifdef _SPECGLOSSMAP
    half roughness = tex2D(_SpecGlossMap, uv).r;
#else
    half roughness = _Glossiness;
#endif
#ifdef _METALLICGLOSSMAP
    half metallic = tex2D(_MetallicGlossMap, uv).r;
#else
    half metallic = _Metallic;
#endif
    return half2(metallic, 1.0 - roughness);
}

half3 Emission(float2 uv)
{
#ifdef _EMISSION
    return tex2D(_EmissionMap, uv).rgb * _EmissionColor.rgb;
#else
    return 0;
#endif
}

#ifdef _NORMALMAP
// The normal map (strength _BumpScale), with the detail normal map blended
// on top where the detail mask says (detail keywords only).
half3 NormalInTangentSpace(float4 texcoords)
{
    half3 base = UnpackScaleNormal(tex2D(_BumpMap, texcoords.xy), _BumpScale);
#if _DETAIL
    half3 detail = UnpackScaleNormal(tex2D(_DetailNormalMap, texcoords.zw), _DetailNormalMapScale);
    return FacetStdApplyDetailNormal(base, detail, DetailMask(texcoords.xy));
#else
    return base;
#endif
}
#endif

// Parallax: both UV pairs shifted along the tangent-space view direction by
// the height in _ParallaxMap.g scaled by _Parallax.
float4 Parallax(float4 texcoords, half3 viewDir)
{
#if defined(_PARALLAXMAP)
    float2 shift = ParallaxOffset(tex2D(_ParallaxMap, texcoords.xy).g, _Parallax, viewDir);
    texcoords.xy += shift;
    texcoords.zw += shift;
#endif
    return texcoords;
}

#endif // UNITY_STANDARD_INPUT_INCLUDED
