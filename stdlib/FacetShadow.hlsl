// Shadow-map lookups of the pass's light. A directional light's receivers
// (SHADOWS_SCREEN) read the screen-space pass's mask (FacetScreenShadow);
// that pass and spot lights' receivers (SHADOWS_DEPTH) look the map up: the
// runtime renders the light's ShadowCaster depth into _ShadowMapTexture and fills
//   unity_WorldToShadow[0]: world -> (u, v, depth, w) of that map, depth 0..1
//     from the light, not reversed (w = 1 for a directional light);
//   _LightShadowData.x: 1 - shadow strength (the shadowed value);
//   _LightShadowData.y: 1 for soft shadows: 3x3 comparisons averaged
//     (percentage-closer filtering), chosen at run time because Unity's
//     ForwardBase variants have no SHADOWS_SOFT (its screen-space pass filters);
//   _ShadowMapTexture_TexelSize: (1/size, 1/size, size, size).
// A point light (SHADOWS_CUBE) has a distance cube instead (below).
#ifndef FACET_SHADOW_INCLUDED
#define FACET_SHADOW_INCLUDED

#include "FacetBuiltins.hlsl"

#if defined(SHADOWS_CUBE)
// A point light's shadow cube (SHADOWS_CUBE), set 1 binding 2: each texel
// holds the distance from the light to the nearest caster along its
// direction, over the light's range (_LightPositionRange.w), plus the
// caster's bias (UnityCG.cginc's SHADOW_CASTER_FRAGMENT).
#if !defined(SHADOWMAPSAMPLER_DEFINED) && !defined(SHADOWMAPSAMPLER_AND_TEXELSIZE_DEFINED)
samplerCUBE _ShadowMapTexture : register(s2, space1);
#endif
#ifndef SHADOWMAPSAMPLER_DEFINED
#define SHADOWMAPSAMPLER_DEFINED
#endif

float FacetShadowCompareCube(float3 vec, float distance)
{
    return texCUBElod(_ShadowMapTexture, float4(vec, 0.0)).r >= distance ? 1.0 : 0.0;
}

// The light's visibility at `vec` = world position - light position: 1 lit,
// _LightShadowData.x fully shadowed; soft shadows average four lookups
// turned about the direction by a texel and a half, as Unity's soft cube
// shadows do.
float FacetSampleShadowCube(float3 vec)
{
    // 3 % nearer than the receiver: a caster this close behind it in
    // distance is the receiver itself (the cube's texels are wide at a
    // grazing angle), as Unity's _LightProjectionParams.w bias does.
    float distance = length(vec) * _LightPositionRange.w * 0.97;
    float lit;
    if (_LightShadowData.y > 0.5) {
        float spread = 1.5 * _ShadowMapTexture_TexelSize.x * 2.0 * length(vec);
        lit = 0.25 * (FacetShadowCompareCube(vec + float3(spread, spread, spread), distance)
                    + FacetShadowCompareCube(vec + float3(-spread, -spread, spread), distance)
                    + FacetShadowCompareCube(vec + float3(-spread, spread, -spread), distance)
                    + FacetShadowCompareCube(vec + float3(spread, -spread, -spread), distance));
    } else {
        lit = FacetShadowCompareCube(vec, distance);
    }
    return lerp(_LightShadowData.x, 1.0, lit);
}
#else
// The light's shadow map (depth; white without one), set 1 binding 2
// (docs/binding-model.md). As in Unity's shadow library, a program that
// declares _ShadowMapTexture itself before the includes (and says so with
// SHADOWMAPSAMPLER_DEFINED or SHADOWMAPSAMPLER_AND_TEXELSIZE_DEFINED, as
// Internal-ScreenSpaceShadows does) keeps its own declaration, and the
// functions below sample that one.
#if !defined(SHADOWMAPSAMPLER_DEFINED) && !defined(SHADOWMAPSAMPLER_AND_TEXELSIZE_DEFINED)
sampler2D _ShadowMapTexture : register(s2, space1);
#endif
#ifndef SHADOWMAPSAMPLER_DEFINED
#define SHADOWMAPSAMPLER_DEFINED
#endif

// 1 where the map's depth is not nearer to the light than `depth`, else 0.
float FacetShadowCompare(float2 uv, float depth)
{
    return tex2Dlod(_ShadowMapTexture, float4(uv, 0.0, 0.0)).r >= depth ? 1.0 : 0.0;
}

// The light's visibility at a shadow coordinate whose map covers `region`
// of the texture (min uv, max uv: a cascade's square of the atlas): 1 lit,
// _LightShadowData.x fully shadowed; outside the region, and beyond its far
// plane, lit. Soft shadows' taps stay inside the region.
float FacetSampleShadowIn(float4 shadowCoord, float4 region)
{
    float3 c = shadowCoord.xyz / max(shadowCoord.w, 1e-6);
    if (shadowCoord.w <= 0.0 || any(c.xy < region.xy) || any(c.xy > region.zw) || c.z > 1.0) return 1.0;
    float lit = 0.0;
    if (_LightShadowData.y > 0.5) {
        float2 texel = _ShadowMapTexture_TexelSize.xy;
        for (int y = -1; y <= 1; ++y)
            for (int x = -1; x <= 1; ++x)
                lit += FacetShadowCompare(clamp(c.xy + float2(x, y) * texel, region.xy + 0.5 * texel, region.zw - 0.5 * texel), c.z);
        lit /= 9.0;
    } else {
        lit = FacetShadowCompare(c.xy, c.z);
    }
    return lerp(_LightShadowData.x, 1.0, lit);
}
float FacetSampleShadow(float4 shadowCoord) { return FacetSampleShadowIn(shadowCoord, float4(0.0, 0.0, 1.0, 1.0)); }

// The light's visibility at a world position: for a directional light with
// cascades, the cascade whose slice of the view (_LightSplitsNear ..
// _LightSplitsFar, distances along the camera's forward) holds it, as
// Unity's getCascadeWeights picks it; beyond the last cascade, lit. Without
// cascades the one map (unity_WorldToShadow[0]) covers everything.
float FacetShadowAtWorld(float3 worldPos)
{
    float z = dot(_WorldSpaceCameraPos - worldPos, unity_MatrixV[2].xyz);
    float4 weights = float4(z >= _LightSplitsNear) * float4(z < _LightSplitsFar);
    if (dot(weights, float4(1.0, 1.0, 1.0, 1.0)) <= 0.0) return 1.0;
    int cascade = weights.y > 0.0 ? 1 : (weights.z > 0.0 ? 2 : (weights.w > 0.0 ? 3 : 0));
    float2 cells = max(_FacetShadowCascades.yz, float2(1.0, 1.0));
    float2 origin = float2(cascade % 2, cascade / 2) / cells;
    float4 region = cells.x > 1.0 ? float4(origin, origin + 1.0 / cells) : float4(0.0, 0.0, 1.0, 1.0);
    return FacetSampleShadowIn(mul(unity_WorldToShadow[cascade], float4(worldPos, 1.0)), region);
}

// SHADOWS_SCREEN: _ShadowMapTexture is the screen-space pass's mask of the
// light's visibility; `screenPos` is ComputeScreenPos of the receiver.
float FacetScreenShadow(float4 screenPos)
{
    return tex2Dlod(_ShadowMapTexture, float4(screenPos.xy / max(screenPos.w, 1e-6), 0.0, 0.0)).r;
}
#endif

float4 FacetShadowCoord(float3 worldPos) { return mul(unity_WorldToShadow[0], float4(worldPos, 1.0)); }

#endif // FACET_SHADOW_INCLUDED
