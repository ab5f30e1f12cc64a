// The Standard shader's ShadowCaster pass: vertShadowCaster/fragShadowCaster.
// Depth with normal-offset and linear bias for directional/spot lights, the
// distance to the light for point lights (SHADOWS_CUBE). Cutout
// (_ALPHATEST_ON) clips at _Cutoff; Fade/Transparent (_ALPHABLEND_ON,
// _ALPHAPREMULTIPLY_ON) cast dithered shadows (a 4x4 ordered dither on the
// alpha, where Unity samples its _DitherMaskLOD texture).
#ifndef UNITY_STANDARD_SHADOW_INCLUDED
#define UNITY_STANDARD_SHADOW_INCLUDED

#ifndef UNITY_PASS_SHADOWCASTER
#define UNITY_PASS_SHADOWCASTER 1
#endif

#include "UnityCG.cginc"
#include "UnityShaderVariables.cginc"
#include "UnityStandardConfig.cginc"
#include "UnityStandardUtils.cginc"
#include "UnityStandardInput.cginc"
#include "UnityStandardCore.cginc"

#if defined(_ALPHABLEND_ON) || defined(_ALPHAPREMULTIPLY_ON)
#define UNITY_STANDARD_USE_DITHER_MASK 1
#endif
#if defined(_ALPHATEST_ON) || defined(_ALPHABLEND_ON) || defined(_ALPHAPREMULTIPLY_ON)
#define UNITY_STANDARD_USE_SHADOW_UVS 1
#endif

struct VertexOutputShadowCaster
{
    V2F_SHADOW_CASTER_NOPOS         // TEXCOORD0 for point lights
    UNITY_POSITION(pos);
    float2 tex : TEXCOORD1;
#if defined(_PARALLAXMAP) && defined(UNITY_STANDARD_USE_SHADOW_UVS)
    half3 viewDirForParallax : TEXCOORD2;
#endif
};

VertexOutputShadowCaster vertShadowCaster(VertexInput v)
{
    UNITY_SETUP_INSTANCE_ID(v);
    VertexOutputShadowCaster o;
    UNITY_INITIALIZE_OUTPUT(VertexOutputShadowCaster, o);
    TRANSFER_SHADOW_CASTER_NORMALOFFSET(o)
    o.tex = TRANSFORM_TEX(v.uv0, _MainTex);
#if defined(_PARALLAXMAP) && defined(UNITY_STANDARD_USE_SHADOW_UVS)
    TANGENT_SPACE_ROTATION;
    o.viewDirForParallax = mul(rotation, ObjSpaceViewDir(v.vertex));
#endif
    return o;
}

// FacetDitherThreshold (the 4x4 Bayer threshold): FacetCore.hlsl.

half4 fragShadowCaster(VertexOutputShadowCaster i) : SV_Target
{
#if defined(UNITY_STANDARD_USE_SHADOW_UVS)
    float2 tex = i.tex;
#if defined(_PARALLAXMAP)
    tex = Parallax(float4(tex, 0, 0), normalize(i.viewDirForParallax)).xy;
#endif
    half alpha = Alpha(tex);
#if defined(_ALPHATEST_ON)
    clip(alpha - _Cutoff);
#endif
#if defined(UNITY_STANDARD_USE_DITHER_MASK)
#if defined(_ALPHAPREMULTIPLY_ON)
    // The reflective share of premultiplied materials stays opaque.
    FragmentCommonData s = UNITY_SETUP_BRDF_INPUT(float4(tex, 0, 0));
    half outModifiedAlpha;
    PreMultiplyAlpha(half3(0, 0, 0), alpha, s.oneMinusReflectivity, outModifiedAlpha);
    alpha = outModifiedAlpha;
#endif
    clip(alpha - FacetDitherThreshold(i.pos.xy));
#endif
#endif
    SHADOW_CASTER_FRAGMENT(i)
}

#endif // UNITY_STANDARD_SHADOW_INCLUDED
