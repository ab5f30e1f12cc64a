// Light colour, the specular colour property, and the structs lighting
// functions pass around.
#ifndef UNITY_LIGHTING_COMMON_INCLUDED
#define UNITY_LIGHTING_COMMON_INCLUDED

#include "UnityShaderVariables.cginc"

// Lighting functions add indirect (ambient, reflection) light only where it
// belongs: once per object, in ForwardBase (and the deferred base pass), not
// once per extra light in ForwardAdd. The pass defines UNITY_PASS_* before
// its includes (the surface-shader lowering does it for generated passes).
#if (defined(UNITY_PASS_FORWARDBASE) || defined(UNITY_PASS_DEFERRED)) && !defined(UNITY_LIGHT_FUNCTION_APPLY_INDIRECT)
#define UNITY_LIGHT_FUNCTION_APPLY_INDIRECT
#endif

// The colour * intensity of the pass's light (FacetPerLight, set 1). A shader
// that declares its own `float4 _LightColor0;` without this file gets a loose
// uniform instead, which the runtime fills by name.
#define _LightColor0 _FacetLightColor0

// A material property (it lands in "$Globals"): declare it in Properties, not
// in the program.
fixed4 _SpecColor;

struct UnityLight
{
    half3 color;  // colour * intensity, attenuation not included
    half3 dir;    // world space, towards the light
    half ndotl;   // deprecated; not filled
};

struct UnityIndirect
{
    half3 diffuse;   // indirect (ambient) diffuse irradiance
    half3 specular;  // prefiltered environment radiance
};

struct UnityGI
{
    UnityLight light;
    UnityIndirect indirect;
};

struct UnityGIInput
{
    UnityLight light;
    float3 worldPos;
    half3 worldViewDir;
    half atten;
    half3 ambient;
    float4 lightmapUV;  // facet has no lightmaps; kept for source compatibility
    float4 boxMax[2];
    float4 boxMin[2];
    float4 probePosition[2];
    float4 probeHDR[2];
};

#endif // UNITY_LIGHTING_COMMON_INCLUDED
