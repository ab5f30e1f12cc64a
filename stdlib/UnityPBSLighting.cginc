// The physically based surface-shader lighting models Standard (metallic)
// and StandardSpecular, their output structs and the UNITY_BRDF_PBS choice.
#ifndef UNITY_PBS_LIGHTING_INCLUDED
#define UNITY_PBS_LIGHTING_INCLUDED

#include "UnityShaderVariables.cginc"
#include "UnityStandardConfig.cginc"
#include "UnityLightingCommon.cginc"
#include "UnityGlobalIllumination.cginc"
#include "UnityStandardBRDF.cginc"
#include "UnityStandardUtils.cginc"

// The BRDF of the Standard path. A shader that defines UNITY_BRDF_PBS before
// including this file keeps its own (the same 8 arguments as BRDF1_Unity_PBS).
// Otherwise: below shader model 3.0, or with UNITY_PBS_USE_BRDF3, the
// normalized-Phong tier; with UNITY_PBS_USE_BRDF2 the minimalist
// Cook-Torrance; else (UNITY_PBS_USE_BRDF1, the surface analysis pass, or
// no tier given) the Disney/GGX tier.
#if !defined(UNITY_BRDF_PBS)
#if (defined(SHADER_TARGET) && SHADER_TARGET < 30) || defined(UNITY_PBS_USE_BRDF3)
#define UNITY_BRDF_PBS BRDF3_Unity_PBS
#elif defined(UNITY_PBS_USE_BRDF2)
#define UNITY_BRDF_PBS BRDF2_Unity_PBS
#else
#define UNITY_BRDF_PBS BRDF1_Unity_PBS
#endif
#endif

struct SurfaceOutputStandard
{
    fixed3 Albedo;     // base (diffuse or specular) colour
    float3 Normal;     // tangent space when surf writes it; world space when lighting runs
    half3 Emission;
    half Metallic;     // 0 = non-metal, 1 = metal
    half Smoothness;   // 0 = rough, 1 = smooth
    half Occlusion;    // default 1
    fixed Alpha;       // for transparencies
};

struct SurfaceOutputStandardSpecular
{
    fixed3 Albedo;     // diffuse colour
    fixed3 Specular;   // specular colour
    float3 Normal;
    half3 Emission;
    half Smoothness;
    half Occlusion;
    fixed Alpha;
};

// ---- Standard (metallic) ----------------------------------------------------------------
inline half4 LightingStandard(SurfaceOutputStandard s, float3 viewDir, UnityGI gi)
{
    s.Normal = normalize(s.Normal);
    half oneMinusReflectivity;
    half3 specColor;
    s.Albedo = DiffuseAndSpecularFromMetallic(s.Albedo, s.Metallic, specColor, oneMinusReflectivity);
    half outputAlpha;
    s.Albedo = PreMultiplyAlpha(s.Albedo, s.Alpha, oneMinusReflectivity, outputAlpha);
    half4 c = UNITY_BRDF_PBS(s.Albedo, specColor, oneMinusReflectivity, s.Smoothness, s.Normal, viewDir, gi.light,
                             gi.indirect);
    c.a = outputAlpha;
    return c;
}

inline void LightingStandard_GI(SurfaceOutputStandard s, UnityGIInput data, inout UnityGI gi)
{
    FacetSetupGIInputProbes(data);
    Unity_GlossyEnvironmentData g = UnityGlossyEnvironmentSetup(s.Smoothness, data.worldViewDir, s.Normal,
                                                                lerp(unity_ColorSpaceDielectricSpec.rgb, s.Albedo, s.Metallic));
    gi = UnityGlobalIllumination(data, s.Occlusion, s.Normal, g);
}

// The deferred path's G-buffer (UnityGBuffer.cginc's layout: albedo +
// occlusion, specular + smoothness, normal) and, returned for the light
// buffer, what the surface gives off by itself: emission and the indirect
// light of gi (ambient, reflections); the lights come later from the G-buffer.
inline half4 LightingStandard_Deferred(SurfaceOutputStandard s, float3 viewDir, UnityGI gi, out half4 outGBuffer0,
                                       out half4 outGBuffer1, out half4 outGBuffer2)
{
    half oneMinusReflectivity;
    half3 specColor;
    s.Albedo = DiffuseAndSpecularFromMetallic(s.Albedo, s.Metallic, specColor, oneMinusReflectivity);
    half4 c = UNITY_BRDF_PBS(s.Albedo, specColor, oneMinusReflectivity, s.Smoothness, s.Normal, viewDir, gi.light,
                             gi.indirect);
    outGBuffer0 = half4(s.Albedo, s.Occlusion);
    outGBuffer1 = half4(specColor, s.Smoothness);
    outGBuffer2 = half4(s.Normal * 0.5 + 0.5, 1);
    return half4(s.Emission + c.rgb, 1);  // what the surface gives off: emission, ambient, reflections
}

// ---- StandardSpecular --------------------------------------------------------------------
inline half4 LightingStandardSpecular(SurfaceOutputStandardSpecular s, float3 viewDir, UnityGI gi)
{
    s.Normal = normalize(s.Normal);
    half oneMinusReflectivity;
    s.Albedo = EnergyConservationBetweenDiffuseAndSpecular(s.Albedo, s.Specular, oneMinusReflectivity);
    half outputAlpha;
    s.Albedo = PreMultiplyAlpha(s.Albedo, s.Alpha, oneMinusReflectivity, outputAlpha);
    half4 c = UNITY_BRDF_PBS(s.Albedo, s.Specular, oneMinusReflectivity, s.Smoothness, s.Normal, viewDir, gi.light,
                             gi.indirect);
    c.a = outputAlpha;
    return c;
}

inline void LightingStandardSpecular_GI(SurfaceOutputStandardSpecular s, UnityGIInput data, inout UnityGI gi)
{
    FacetSetupGIInputProbes(data);
    Unity_GlossyEnvironmentData g = UnityGlossyEnvironmentSetup(s.Smoothness, data.worldViewDir, s.Normal, s.Specular);
    gi = UnityGlobalIllumination(data, s.Occlusion, s.Normal, g);
}

inline half4 LightingStandardSpecular_Deferred(SurfaceOutputStandardSpecular s, float3 viewDir, UnityGI gi,
                                               out half4 outGBuffer0, out half4 outGBuffer1, out half4 outGBuffer2)
{
    half oneMinusReflectivity;
    s.Albedo = EnergyConservationBetweenDiffuseAndSpecular(s.Albedo, s.Specular, oneMinusReflectivity);
    half4 c = UNITY_BRDF_PBS(s.Albedo, s.Specular, oneMinusReflectivity, s.Smoothness, s.Normal, viewDir, gi.light,
                             gi.indirect);
    outGBuffer0 = half4(s.Albedo, s.Occlusion);
    outGBuffer1 = half4(s.Specular, s.Smoothness);
    outGBuffer2 = half4(s.Normal * 0.5 + 0.5, 1);
    return half4(s.Emission + c.rgb, 1);  // what the surface gives off: emission, ambient, reflections
}

#endif // UNITY_PBS_LIGHTING_INCLUDED
