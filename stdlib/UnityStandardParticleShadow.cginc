// The Standard particle shaders' ShadowCaster pass: vertParticleShadowCaster /
// fragParticleShadowCaster. Cut-out (_ALPHATEST_ON) and blended
// (_ALPHABLEND_ON, _ALPHAPREMULTIPLY_ON) particles read the texture's alpha
// (flipbook-blended under _REQUIRE_UV2) times the vertex alpha; blended ones
// cast where it is over 0.5, or by ordered dither under
// UNITY_USE_DITHER_MASK_FOR_ALPHABLENDED_SHADOWS (a 4x4 Bayer threshold,
// not Unity's _DitherMaskLOD texture).
#ifndef UNITY_STANDARD_PARTICLE_SHADOW_INCLUDED
#define UNITY_STANDARD_PARTICLE_SHADOW_INCLUDED

#if _REQUIRE_UV2
#define _FLIPBOOK_BLENDING 1
#endif

#include "UnityCG.cginc"
#include "UnityShaderVariables.cginc"
#include "UnityStandardConfig.cginc"
#include "UnityStandardUtils.cginc"
#include "UnityStandardParticleInstancing.cginc"
#include "FacetParticles.hlsl"

#if (defined(_ALPHABLEND_ON) || defined(_ALPHAPREMULTIPLY_ON)) && defined(UNITY_USE_DITHER_MASK_FOR_ALPHABLENDED_SHADOWS)
#define UNITY_STANDARD_USE_DITHER_MASK 1
#endif
#if defined(_ALPHATEST_ON) || defined(_ALPHABLEND_ON) || defined(_ALPHAPREMULTIPLY_ON)
#define UNITY_STANDARD_USE_SHADOW_UVS 1
#endif
#if !defined(V2F_SHADOW_CASTER_NOPOS_IS_EMPTY) || defined(UNITY_STANDARD_USE_SHADOW_UVS)
#define UNITY_STANDARD_USE_SHADOW_OUTPUT_STRUCT 1
#endif

#ifdef _ALPHATEST_ON
half _Cutoff;
#endif
sampler2D _MainTex;
float4 _MainTex_ST;
half _Metallic;
#ifdef _METALLICGLOSSMAP
sampler2D _MetallicGlossMap;
#endif

half MetallicSetup_ShadowGetOneMinusReflectivity(half2 uv)
{
#ifdef _METALLICGLOSSMAP
    return OneMinusReflectivityFromMetallic(tex2D(_MetallicGlossMap, uv).r);
#else
    return OneMinusReflectivityFromMetallic(_Metallic);
#endif
}

struct VertexInput
{
    float4 vertex : POSITION;
    float3 normal : NORMAL;
    fixed4 color : COLOR;
#if defined(_FLIPBOOK_BLENDING)
    float4 texcoords : TEXCOORD0;
    float texcoordBlend : TEXCOORD1;
#else
    float2 texcoords : TEXCOORD0;
#endif
    UNITY_VERTEX_INPUT_INSTANCE_ID
};

#ifdef UNITY_STANDARD_USE_SHADOW_OUTPUT_STRUCT
struct VertexOutputShadowCaster
{
    V2F_SHADOW_CASTER_NOPOS
#ifdef UNITY_STANDARD_USE_SHADOW_UVS
    float2 texcoord : TEXCOORD1;
#ifdef _FLIPBOOK_BLENDING
    float3 texcoord2AndBlend : TEXCOORD2;
#endif
    fixed4 color : TEXCOORD3;
#endif
};
#endif

void vertParticleShadowCaster(VertexInput v,
#ifdef UNITY_STANDARD_USE_SHADOW_OUTPUT_STRUCT
                              out VertexOutputShadowCaster o,
#endif
                              out float4 opos : SV_POSITION)
{
    UNITY_SETUP_INSTANCE_ID(v);
    TRANSFER_SHADOW_CASTER_NOPOS(o, opos)
#ifdef UNITY_STANDARD_USE_SHADOW_UVS
#ifdef _FLIPBOOK_BLENDING
    o.texcoord = v.texcoords.xy;
    o.texcoord2AndBlend = float3(v.texcoords.zw, v.texcoordBlend);
#else
    o.texcoord = TRANSFORM_TEX(v.texcoords.xy, _MainTex);
#endif
    o.color = v.color;
#endif
}

half4 fragParticleShadowCaster(
#ifdef UNITY_STANDARD_USE_SHADOW_OUTPUT_STRUCT
    VertexOutputShadowCaster i
#endif
#ifdef UNITY_STANDARD_USE_DITHER_MASK
    , UNITY_VPOS_TYPE vpos : VPOS
#endif
    ) : SV_Target
{
#ifdef UNITY_STANDARD_USE_SHADOW_UVS
#ifdef _FLIPBOOK_BLENDING
    half alpha = FacetFlipbookSample(_MainTex, i.texcoord, i.texcoord2AndBlend.xy, i.texcoord2AndBlend.z).a;
#else
    half alpha = tex2D(_MainTex, i.texcoord).a;
#endif
    alpha *= i.color.a;
#ifdef _ALPHATEST_ON
    clip(alpha - _Cutoff);
#endif
#if defined(_ALPHABLEND_ON) || defined(_ALPHAPREMULTIPLY_ON)
#ifdef _ALPHAPREMULTIPLY_ON
    half premultipliedAlpha;
    PreMultiplyAlpha(half3(0, 0, 0), alpha, MetallicSetup_ShadowGetOneMinusReflectivity(i.texcoord), premultipliedAlpha);
    alpha = premultipliedAlpha;
#endif
#ifdef UNITY_STANDARD_USE_DITHER_MASK
    clip(alpha - FacetDitherThreshold(vpos.xy));
#else
    clip(alpha - 0.5);
#endif
#endif
#endif
    SHADOW_CASTER_FRAGMENT(i)
}

#endif // UNITY_STANDARD_PARTICLE_SHADOW_INCLUDED
