// The legacy lighting models for forward vertex/fragment and surface code:
// SurfaceOutput with Lambert and Blinn-Phong. The physically based models and
// the GI functions arrive with the full library (UnityPBSLighting.cginc etc.).
#ifndef LIGHTING_INCLUDED
#define LIGHTING_INCLUDED

#include "UnityLightingCommon.cginc"
#include "UnityCG.cginc"

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

#endif // LIGHTING_INCLUDED
