// Light attenuation and shadow macros for ForwardBase/ForwardAdd
// vertex/fragment programs. Shadows: SHADOWS_SCREEN (directional lights)
// and SHADOWS_DEPTH (spot lights) sample the light's shadow map through a
// light-space coordinate (FacetShadow.hlsl), as Unity does where it has no
// screen-space shadows; SHADOWS_CUBE (point lights) samples the light's
// distance cube towards the world position. Attenuation follows
// POINT/SPOT/DIRECTIONAL/DIRECTIONAL_COOKIE (FacetLight.hlsl).
#ifndef AUTOLIGHT_INCLUDED
#define AUTOLIGHT_INCLUDED

#include "HLSLSupport.cginc"
#include "UnityShaderVariables.cginc"
#include "FacetLight.hlsl"
#include "FacetShadow.hlsl"
#include "UnityShadowLibrary.cginc"

// UNITY_ATTEN_CHANNEL: HLSLSupport.cginc.

// Shadow-coordinate types and shadow-map declarations, as Unity spells them.
// unityShadowCoord*: UnityShadowLibrary.cginc.
// UNITY_DECLARE_SHADOWMAP, UNITY_SAMPLE_SHADOW(_PROJ): HLSLSupport.cginc.

// ---- shadows ------------------------------------------------------------------------
// SHADOWS_SCREEN (a directional light): as in Unity, the runtime's
// screen-space pass (Hidden/Internal-ScreenSpaceShadows) has looked the
// light's map up at every pixel of the camera depth texture; SHADOW_COORDS
// is the screen position, TRANSFER_SHADOW fills it from the output's `pos`
// (which must be set before, as in Unity), and the attenuation macros read
// the mask there (FacetScreenShadow).
// SHADOWS_DEPTH (a spot light): SHADOW_COORDS adds the interpolated world
// position, TRANSFER_SHADOW fills it from `v.vertex` (the vertex input must
// be called v, as in Unity); the attenuation macros look the map up there
// (UNITY_SHADOW_ATTENUATION takes the world position it is given).
#if defined(SHADOWS_SCREEN)
#define SHADOW_COORDS(idx1) float4 _ShadowCoord : TEXCOORD##idx1;
#define UNITY_SHADOW_COORDS(idx1) SHADOW_COORDS(idx1)
#define TRANSFER_SHADOW(a) a._ShadowCoord = ComputeScreenPos(a.pos);
#define UNITY_TRANSFER_SHADOW(a, coord) TRANSFER_SHADOW(a)
#define SHADOW_ATTENUATION(a) FacetScreenShadow(a._ShadowCoord)
#define UNITY_SHADOW_ATTENUATION(a, worldPos) FacetScreenShadow(a._ShadowCoord)
#define UNITY_TRANSFER_SHADOW_WPOS(a, coord, wpos) TRANSFER_SHADOW(a)
#elif defined(SHADOWS_DEPTH)
#define SHADOW_COORDS(idx1) float4 _ShadowCoord : TEXCOORD##idx1;
#define UNITY_SHADOW_COORDS(idx1) SHADOW_COORDS(idx1)
#define TRANSFER_SHADOW(a) a._ShadowCoord = float4(mul(unity_ObjectToWorld, float4(v.vertex.xyz, 1.0)).xyz, 1.0);
#define UNITY_TRANSFER_SHADOW(a, coord) TRANSFER_SHADOW(a)
#define SHADOW_ATTENUATION(a) FacetShadowAtWorld(a._ShadowCoord.xyz)
#define UNITY_SHADOW_ATTENUATION(a, worldPos) FacetShadowAtWorld(worldPos)
#define UNITY_TRANSFER_SHADOW_WPOS(a, coord, wpos) a._ShadowCoord = float4(wpos, 1.0);
#elif defined(SHADOWS_CUBE)
// The vector from the light to the vertex, as Unity's cube form keeps it.
#define SHADOW_COORDS(idx1) float3 _ShadowCoord : TEXCOORD##idx1;
#define UNITY_SHADOW_COORDS(idx1) SHADOW_COORDS(idx1)
#define TRANSFER_SHADOW(a) a._ShadowCoord = mul(unity_ObjectToWorld, float4(v.vertex.xyz, 1.0)).xyz - _LightPositionRange.xyz;
#define UNITY_TRANSFER_SHADOW(a, coord) TRANSFER_SHADOW(a)
#define SHADOW_ATTENUATION(a) FacetSampleShadowCube(a._ShadowCoord)
#define UNITY_SHADOW_ATTENUATION(a, worldPos) FacetSampleShadowCube((worldPos) - _LightPositionRange.xyz)
#define UNITY_TRANSFER_SHADOW_WPOS(a, coord, wpos) a._ShadowCoord = (wpos) - _LightPositionRange.xyz;
#else
#define SHADOW_COORDS(idx1)
#define UNITY_SHADOW_COORDS(idx1)
#define TRANSFER_SHADOW(a)
#define UNITY_TRANSFER_SHADOW(a, coord)
#define SHADOW_ATTENUATION(a) 1.0
#define UNITY_SHADOW_ATTENUATION(a, worldPos) 1.0
#define UNITY_TRANSFER_SHADOW_WPOS(a, coord, wpos)
#endif
#define UNITY_SHADOW_W(_w) _w
#define READ_SHADOW_COORDS(a) a._ShadowCoord
#define UNITY_READ_SHADOW_COORDS(input) READ_SHADOW_COORDS(input)

// Realtime shadow at a world position (SHADOWS_SCREEN: the screen-space
// mask at screenPos; SHADOWS_DEPTH: the light's map through
// unity_WorldToShadow; SHADOWS_CUBE: the light's distance cube), mixed
// with baked occlusion and faded with distance as Unity's forward path does.
half UnityComputeForwardShadows(float2 lightmapUV, float3 worldPos, float4 screenPos)
{
    float zDist = dot(_WorldSpaceCameraPos - worldPos, UNITY_MATRIX_V[2].xyz);
    half fade = UnityComputeShadowFade(UnityComputeShadowFadeDistance(worldPos, zDist));
    half baked = UnitySampleBakedOcclusion(lightmapUV, worldPos);
#if defined(SHADOWS_SCREEN)
    half realtime = FacetScreenShadow(screenPos);
#elif defined(SHADOWS_DEPTH)
    half realtime = FacetShadowAtWorld(worldPos);
#elif defined(SHADOWS_CUBE)
    half realtime = FacetSampleShadowCube(worldPos - _LightPositionRange.xyz);
#else
    half realtime = 1.0;
#endif
    return UnityMixRealtimeAndBakedShadows(realtime, baked, fade);
}

// ---- light coordinates ----------------------------------------------------------
// LIGHTING_COORDS(idx1, idx2) adds the interpolators (light space position in
// TEXCOORD<idx1>, shadow coordinates in TEXCOORD<idx2>); TRANSFER_VERTEX_TO_FRAGMENT(o)
// fills them from `v.vertex` (so the vertex input must be called v, as in Unity).
#if defined(POINT) || defined(POINT_COOKIE) || defined(SPOT) || defined(DIRECTIONAL_COOKIE)
#define DECLARE_LIGHT_COORDS(idx) float3 _LightCoord : TEXCOORD##idx;
#define COMPUTE_LIGHT_COORDS(a) a._LightCoord = FacetLightCoord(mul(unity_ObjectToWorld, float4(v.vertex.xyz, 1.0)).xyz);
#define LIGHT_ATTENUATION(a) (FacetLightAttenuationAt(a._LightCoord) * SHADOW_ATTENUATION(a))
#else
#define DECLARE_LIGHT_COORDS(idx)
#define COMPUTE_LIGHT_COORDS(a)
#define LIGHT_ATTENUATION(a) SHADOW_ATTENUATION(a)
#endif

// Unity's spot helpers: the cookie's alpha at a projective light coordinate,
// and the distance falloff (facet's analytic one instead of Unity's
// _LightTextureB0 ramp).
inline fixed UnitySpotCookie(unityShadowCoord4 LightCoord) { return tex2D(_LightTexture0, LightCoord.xy / LightCoord.w + 0.5).w; }
inline fixed UnitySpotAttenuate(unityShadowCoord3 LightCoord) { return FacetDistanceAttenuation(LightCoord); }
// The light-space position at worldPos, named lightCoord.
#define DECLARE_LIGHT_COORD(input, worldPos) unityShadowCoord4 lightCoord = mul(unity_WorldToLight, unityShadowCoord4(worldPos, 1))

#define LIGHTING_COORDS(idx1, idx2) DECLARE_LIGHT_COORDS(idx1) SHADOW_COORDS(idx2)
#define UNITY_LIGHTING_COORDS(idx1, idx2) DECLARE_LIGHT_COORDS(idx1) UNITY_SHADOW_COORDS(idx2)
#define TRANSFER_VERTEX_TO_FRAGMENT(a) COMPUTE_LIGHT_COORDS(a) TRANSFER_SHADOW(a)
#define UNITY_TRANSFER_LIGHTING(a, coord) COMPUTE_LIGHT_COORDS(a) UNITY_TRANSFER_SHADOW(a, coord)

// Attenuation at a world position times shadowing, computed in the fragment
// stage. The declaration ends in its ';', as Unity's does (shaders call it
// without one).
#define UNITY_LIGHT_ATTENUATION(destName, input, worldPos) \
    float destName = FacetLightAttenuation(worldPos) * UNITY_SHADOW_ATTENUATION(input, worldPos);

#endif // AUTOLIGHT_INCLUDED
