// The legacy lighting models for forward vertex/fragment and surface code:
// SurfaceOutput with Lambert and Blinn-Phong, each in its forward form, its
// _GI form (fills the UnityGI: SH ambient, no reflection) and the
// _Deferred form of the deferred path (the G-buffer; the light pass lights
// it with the Standard BRDF, as Unity's does) and the _PrePass form of the
// legacy light pre-pass path (compile-compatible: facet has no pre-pass).
// The physically based models are in
// UnityPBSLighting.cginc.
#ifndef LIGHTING_INCLUDED
#define LIGHTING_INCLUDED

#include "UnityLightingCommon.cginc"
#include "UnityCG.cginc"
#include "UnityGlobalIllumination.cginc"

struct SurfaceOutput
{
    fixed3 Albedo;
    fixed3 Normal;    // world space when lighting runs
    fixed3 Emission;
    half Specular;    // specular power / 128
    fixed Gloss;      // specular intensity
    fixed Alpha;
};

// Lambert: albedo * light * max(0, N.L), plus indirect diffuse when the pass
// defines UNITY_LIGHT_FUNCTION_APPLY_INDIRECT.
inline fixed4 UnityLambertLight(SurfaceOutput s, UnityLight light)
{
    fixed diff = max(0, dot(s.Normal, light.dir));
    fixed4 c;
    c.rgb = s.Albedo * light.color * diff;
    c.a = s.Alpha;
    return c;
}

inline fixed4 LightingLambert(SurfaceOutput s, UnityGI gi)
{
    fixed4 c = UnityLambertLight(s, gi.light);
#ifdef UNITY_LIGHT_FUNCTION_APPLY_INDIRECT
    c.rgb += s.Albedo * gi.indirect.diffuse;
#endif
    return c;
}

// Blinn-Phong: Lambert plus _SpecColor * light * Gloss * max(0, N.H)^(Specular * 128).
inline fixed4 UnityBlinnPhongLight(SurfaceOutput s, half3 viewDir, UnityLight light)
{
    half3 h = normalize(light.dir + viewDir);
    fixed diff = max(0, dot(s.Normal, light.dir));
    float nh = max(0, dot(s.Normal, h));
    float spec = pow(nh, s.Specular * 128.0) * s.Gloss;
    fixed4 c;
    c.rgb = s.Albedo * light.color * diff + light.color * _SpecColor.rgb * spec;
    c.a = s.Alpha;
    return c;
}

inline fixed4 LightingBlinnPhong(SurfaceOutput s, half3 viewDir, UnityGI gi)
{
    fixed4 c = UnityBlinnPhongLight(s, viewDir, gi.light);
#ifdef UNITY_LIGHT_FUNCTION_APPLY_INDIRECT
    c.rgb += s.Albedo * gi.indirect.diffuse;
#endif
    return c;
}

// The name the Blinn-Phong core goes by in older texts.
inline fixed4 UnityPhongLight(SurfaceOutput s, half3 viewDir, UnityLight light) { return UnityBlinnPhongLight(s, viewDir, light); }

inline void LightingLambert_GI(SurfaceOutput s, UnityGIInput data, inout UnityGI gi)
{
    gi = UnityGlobalIllumination(data, 1.0, s.Normal);
}

inline void LightingBlinnPhong_GI(SurfaceOutput s, UnityGIInput data, inout UnityGI gi)
{
    gi = UnityGlobalIllumination(data, 1.0, s.Normal);
}

// G-buffer: albedo, specular colour * gloss with the spec power in alpha,
// normal; returns the indirect diffuse light.
inline half4 LightingLambert_Deferred(SurfaceOutput s, UnityGI gi, out half4 outGBuffer0, out half4 outGBuffer1,
                                      out half4 outGBuffer2)
{
    outGBuffer0 = half4(s.Albedo, 1);
    outGBuffer1 = half4(0, 0, 0, 0);
    outGBuffer2 = half4(s.Normal * 0.5 + 0.5, 1);
    half4 emission = half4(s.Emission, 1);
#ifdef UNITY_LIGHT_FUNCTION_APPLY_INDIRECT
    emission.rgb += s.Albedo * gi.indirect.diffuse;
#endif
    return emission;
}

inline half4 LightingBlinnPhong_Deferred(SurfaceOutput s, half3 viewDir, UnityGI gi, out half4 outGBuffer0,
                                         out half4 outGBuffer1, out half4 outGBuffer2)
{
    outGBuffer0 = half4(s.Albedo, 1);
    outGBuffer1 = half4(_SpecColor.rgb * s.Gloss, s.Specular);
    outGBuffer2 = half4(s.Normal * 0.5 + 0.5, 1);
    half4 emission = half4(s.Emission, 1);
#ifdef UNITY_LIGHT_FUNCTION_APPLY_INDIRECT
    emission.rgb += s.Albedo * gi.indirect.diffuse;
#endif
    return emission;
}

// Light pre-pass: `light` is the accumulated light buffer (rgb diffuse
// light, a = specular intensity).
inline fixed4 LightingLambert_PrePass(SurfaceOutput s, half4 light)
{
    fixed4 c;
    c.rgb = s.Albedo * light.rgb;
    c.a = s.Alpha;
    return c;
}

inline fixed4 LightingBlinnPhong_PrePass(SurfaceOutput s, half4 light)
{
    fixed spec = light.a * s.Gloss;
    fixed4 c;
    c.rgb = (s.Albedo * light.rgb + light.rgb * _SpecColor.rgb * spec);
    c.a = s.Alpha + spec * _SpecColor.a;
    return c;
}

#endif // LIGHTING_INCLUDED
