// Attenuation of the pass's light, chosen by the keyword of the pass
// (DIRECTIONAL, DIRECTIONAL_COOKIE, POINT, SPOT; POINT_COOKIE behaves like
// POINT: cube cookies are not supported). Conventions the runtime follows:
//   unity_WorldToLight: world -> light space with the light at the origin,
//     +Z along a spot light's direction, scaled by 1/range (|p| = 1 at range);
//     a spot's w row is its z row times 2 tan(outer half angle) (Unity's
//     projective cookie: uv = xy / w + 0.5); for DIRECTIONAL_COOKIE, xy is
//     the cookie's uv (repeating every cookie size in the light's XY plane);
//   _FacetSpotParams: x = cos(outer half angle), y = 1/(cos(inner) - cos(outer)),
//     z = 2 tan(outer half angle);
//   _LightTexture0: the cookie (its alpha masks the light); a spot without a
//     cookie gets white, so SPOT always multiplies by the sample.
// Formulas in docs/stdlib.md.
#ifndef FACET_LIGHT_INCLUDED
#define FACET_LIGHT_INCLUDED

#include "FacetBuiltins.hlsl"

// Inverse-square-like falloff 1/(1 + 25 d^2) with d = distance/range, windowed
// by (1 - d^4)^2 so that it reaches exactly 0 at the range.
float FacetDistanceAttenuation(float3 lightCoord)
{
    float d2 = dot(lightCoord, lightCoord);
    float window = saturate(1.0 - d2 * d2);
    return window * window / (1.0 + 25.0 * d2);
}

// Smooth cone falloff between the outer and inner angles of a spot light.
float FacetSpotAttenuation(float3 lightCoord)
{
    float cosAngle = lightCoord.z * rsqrt(max(dot(lightCoord, lightCoord), 1e-12));
    float t = saturate((cosAngle - _FacetSpotParams.x) * _FacetSpotParams.y);
    return t * t * (3.0 - 2.0 * t);
}

// The spot cookie's alpha at a light-space position; uv from the projective
// w = z * 2 tan(outer/2) (kept away from 0 behind the light, where the cone
// falloff is 0 anyway).
float FacetSpotCookie(float3 lightCoord)
{
    float w = max(lightCoord.z * _FacetSpotParams.z, 1e-6);
    return tex2D(_LightTexture0, lightCoord.xy / w + 0.5).w;
}

float3 FacetLightCoord(float3 worldPos) { return mul(unity_WorldToLight, float4(worldPos, 1.0)).xyz; }

// Attenuation from light-space coordinates (FacetLightCoord), shadows excluded.
float FacetLightAttenuationAt(float3 lightCoord)
{
#if defined(POINT) || defined(POINT_COOKIE)
    return FacetDistanceAttenuation(lightCoord);
#elif defined(SPOT)
    return FacetDistanceAttenuation(lightCoord) * FacetSpotAttenuation(lightCoord) * FacetSpotCookie(lightCoord);
#elif defined(DIRECTIONAL_COOKIE)
    return tex2D(_LightTexture0, lightCoord.xy).w;
#else
    return 1.0;
#endif
}

float FacetLightAttenuation(float3 worldPos) { return FacetLightAttenuationAt(FacetLightCoord(worldPos)); }

#endif // FACET_LIGHT_INCLUDED
