// The Standard particle shaders' ShadowCaster pass: vertParticleShadowCaster /
// fragParticleShadowCaster. Cut-out (_ALPHATEST_ON) and blended
// (_ALPHABLEND_ON, _ALPHAPREMULTIPLY_ON) particles read the texture's alpha
// (flipbook-blended under _REQUIRE_UV2) times the vertex alpha; blended ones
// cast where it is over 0.5, or by ordered dither under
// UNITY_USE_DITHER_MASK_FOR_ALPHABLENDED_SHADOWS (a 4x4 Bayer threshold,
// not Unity's _DitherMaskLOD texture).
#ifndef UNITY_STANDARD_PARTICLE_SHADOW_INCLUDED
#define UNITY_STANDARD_PARTICLE_SHADOW_INCLUDED

#ifdef _REQUIRE_UV2
#define _FLIPBOOK_BLENDING 1
#endif

#include "UnityCG.cginc"
#include "UnityShaderVariables.cginc"
#include "UnityStandardConfig.cginc"
#include "UnityStandardUtils.cginc"
#include "UnityStandardParticleInstancing.cginc"
#include "FacetParticles.hlsl"

// What the caster needs: the texture's alpha for cut-out and blended
// particles, dithering for blended ones when the project asks for it, and an
// output struct whenever there is something besides the position to pass.
#if defined(_ALPHATEST_ON) || defined(_ALPHABLEND_ON) || defined(_ALPHAPREMULTIPLY_ON)
#define UNITY_STANDARD_USE_SHADOW_UVS 1
#endif
#if defined(UNITY_STANDARD_USE_SHADOW_UVS) || !defined(V2F_SHADOW_CASTER_NOPOS_IS_EMPTY)
#define UNITY_STANDARD_USE_SHADOW_OUTPUT_STRUCT 1
#endif
#if defined(UNITY_USE_DITHER_MASK_FOR_ALPHABLENDED_SHADOWS) && (defined(_ALPHABLEND_ON) || defined(_ALPHAPREMULTIPLY_ON))
#define UNITY_STANDARD_USE_DITHER_MASK 1
#endif

// Material values the caster reads.
sampler2D _MainTex;
float4 _MainTex_ST;
#ifdef _METALLICGLOSSMAP
sampler2D _MetallicGlossMap;
#endif
half _Metallic;
#ifdef _ALPHATEST_ON
half _Cutoff;
#endif

// Premultiplied particles fade by their reflectivity, as the lit pass does.
half MetallicSetup_ShadowGetOneMinusReflectivity(half2 uv)
{
#ifdef _METALLICGLOSSMAP
    half metallic = tex2D(_MetallicGlossMap, uv).r;
#else
    half metallic = _Metallic;
#endif
    return OneMinusReflectivityFromMetallic(metallic);
}

// Mesh data (the semantics give the locations; half and fixed are float).
struct VertexInput
{
    float4 vertex : POSITION;
    float4 color : COLOR;
    float3 normal : NORMAL;
#ifndef _FLIPBOOK_BLENDING
    float2 texcoords : TEXCOORD0;
#else
    float4 texcoords : TEXCOORD0;   // this frame in xy, the next one in zw
    float texcoordBlend : TEXCOORD1;
#endif
    UNITY_VERTEX_INPUT_INSTANCE_ID
};

#ifdef UNITY_STANDARD_USE_SHADOW_OUTPUT_STRUCT
struct VertexOutputShadowCaster
{
    V2F_SHADOW_CASTER_NOPOS
#ifdef UNITY_STANDARD_USE_SHADOW_UVS
    float4 color : TEXCOORD3;
    float2 texcoord : TEXCOORD1;
#ifdef _FLIPBOOK_BLENDING
    float3 texcoord2AndBlend : TEXCOORD2;
#endif
#endif
};
#endif

// --- facet's helpers ----------------------------------------------------------

#ifdef UNITY_STANDARD_USE_SHADOW_UVS
// The texture's alpha (both flipbook frames blended where on) times the
// vertex alpha.
half FacetParticleShadowAlpha(VertexOutputShadowCaster i)
{
#ifdef _FLIPBOOK_BLENDING
    half texAlpha = FacetFlipbookSample(_MainTex, i.texcoord, i.texcoord2AndBlend.xy, i.texcoord2AndBlend.z).a;
#else
    half texAlpha = tex2D(_MainTex, i.texcoord).a;
#endif
    return texAlpha * i.color.a;
}
#endif

#if defined(_ALPHABLEND_ON) || defined(_ALPHAPREMULTIPLY_ON)
// Blended particles cast where their (premultiplied) alpha passes a
// threshold: 0.5, or the 4x4 ordered dither at the pixel.
void FacetParticleShadowBlendClip(half alpha, half2 uv, float2 pixel)
{
#ifdef _ALPHAPREMULTIPLY_ON
    half premultiplied;
    PreMultiplyAlpha(half3(0, 0, 0), alpha, MetallicSetup_ShadowGetOneMinusReflectivity(uv), premultiplied);
    alpha = premultiplied;
#endif
#ifdef UNITY_STANDARD_USE_DITHER_MASK
    half threshold = FacetDitherThreshold(pixel);
#else
    half threshold = 0.5;
#endif
    clip(alpha - threshold);
}
#endif

// The stage signatures: the interpolator struct only where it has members,
// the pixel position only for dithering.
#ifdef UNITY_STANDARD_USE_SHADOW_OUTPUT_STRUCT
#define FacetShadowCasterOutput out VertexOutputShadowCaster o,
#define FacetShadowCasterInput VertexOutputShadowCaster i
#else
#define FacetShadowCasterOutput
#define FacetShadowCasterInput
#endif
#ifdef UNITY_STANDARD_USE_DITHER_MASK
#define FacetShadowCasterPixel , UNITY_VPOS_TYPE vpos : VPOS
#else
#define FacetShadowCasterPixel
#endif

void vertParticleShadowCaster(VertexInput v, FacetShadowCasterOutput out float4 opos : SV_POSITION)
{
    UNITY_SETUP_INSTANCE_ID(v);
    TRANSFER_SHADOW_CASTER_NOPOS(o, opos)
#ifdef UNITY_STANDARD_USE_SHADOW_UVS
    o.color = v.color;
#ifndef _FLIPBOOK_BLENDING
    o.texcoord = TRANSFORM_TEX(v.texcoords.xy, _MainTex);
#else
    o.texcoord = v.texcoords.xy;
    o.texcoord2AndBlend = float3(v.texcoords.zw, v.texcoordBlend);
#endif
#endif
}

half4 fragParticleShadowCaster(FacetShadowCasterInput FacetShadowCasterPixel) : SV_Target
{
#ifdef UNITY_STANDARD_USE_SHADOW_UVS
    half alpha = FacetParticleShadowAlpha(i);
#ifdef _ALPHATEST_ON
    clip(alpha - _Cutoff);
#endif
#if defined(_ALPHABLEND_ON) || defined(_ALPHAPREMULTIPLY_ON)
#ifdef UNITY_STANDARD_USE_DITHER_MASK
    FacetParticleShadowBlendClip(alpha, i.texcoord, vpos.xy);
#else
    FacetParticleShadowBlendClip(alpha, i.texcoord, float2(0, 0));
#endif
#endif
#endif
    SHADOW_CASTER_FRAGMENT(i)
}

#endif // UNITY_STANDARD_PARTICLE_SHADOW_INCLUDED
