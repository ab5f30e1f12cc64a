// facet's particle helpers behind UnityStandardParticles.cginc and friends:
// flipbook blending, soft-particle and camera fades, and the colour modes of
// the Standard particle shaders. Plain functions of values, so they work for
// the surface Input and the unlit VertexOutput alike.
#ifndef FACET_PARTICLES_INCLUDED
#define FACET_PARTICLES_INCLUDED

#include "FacetCore.hlsl"

// Two flipbook frames blended by `blend`.
float4 FacetFlipbookSample(sampler2D tex, float2 uv, float2 uv2, float blend)
{
    return lerp(tex2D(tex, uv), tex2D(tex, uv2), blend);
}

// 0 where the particle touches the scene, ramping to 1 over 1/invFade eye
// units in front of it (offset by nearFade): sceneEyeDepth from the camera
// depth texture, particleEyeDepth the particle's own eye depth. Off (1) when
// both parameters are 0.
float FacetSoftParticleFade(float sceneEyeDepth, float particleEyeDepth, float nearFade, float invFade)
{
    if (nearFade <= 0.0 && invFade <= 0.0) return 1.0;
    return saturate(invFade * ((sceneEyeDepth - nearFade) - particleEyeDepth));
}

// 0 at nearFade eye units from the camera, 1 from nearFade + 1/invFade on.
float FacetCameraFade(float eyeDepth, float nearFade, float invFade)
{
    return saturate((eyeDepth - nearFade) * invFade);
}

// RGB <-> HSV (hue 0..1), branch-free.
float3 FacetRgbToHsv(float3 c)
{
    float4 k = float4(0.0, -1.0 / 3.0, 2.0 / 3.0, -1.0);
    float4 p = c.g < c.b ? float4(c.bg, k.wz) : float4(c.gb, k.xy);
    float4 q = c.r < p.x ? float4(p.xyw, c.r) : float4(c.r, p.yzx);
    float chroma = q.x - min(q.w, q.y);
    return float3(abs(q.z + (q.w - q.y) / (6.0 * chroma + 1e-10)), chroma / (q.x + 1e-10), q.x);
}
float3 FacetHsvToRgb(float3 hsv)
{
    float3 p = abs(frac(hsv.xxx + float3(1.0, 2.0 / 3.0, 1.0 / 3.0)) * 6.0 - 3.0);
    return hsv.z * lerp(float3(1, 1, 1), saturate(p - 1.0), hsv.y);
}

// The particle colour applied to the texture colour: overlay
// (_COLOROVERLAY_ON), hue and saturation of the particle with the texture's
// value (_COLORCOLOR_ON), add/subtract/difference by addSubDiff.xy
// (_COLORADDSUBDIFF_ON), else multiply.
float4 FacetParticleColorMode(float4 albedo, float4 vertexColor, float4 addSubDiff)
{
#if defined(_COLOROVERLAY_ON)
    float3 screen = 1.0 - 2.0 * (1.0 - albedo.rgb) * (1.0 - vertexColor.rgb);
    float3 multiply = 2.0 * albedo.rgb * vertexColor.rgb;
    return float4(lerp(screen, multiply, step(albedo.rgb, 0.5)), albedo.a * vertexColor.a);
#elif defined(_COLORCOLOR_ON)
    float3 a = FacetRgbToHsv(albedo.rgb);
    float3 b = FacetRgbToHsv(vertexColor.rgb);
    return float4(FacetHsvToRgb(float3(b.x, b.y, a.z)), albedo.a * vertexColor.a);
#elif defined(_COLORADDSUBDIFF_ON)
    float3 rgb = albedo.rgb + vertexColor.rgb * addSubDiff.x;
    return float4(lerp(rgb, abs(rgb), addSubDiff.y), albedo.a * vertexColor.a);
#else
    return albedo * vertexColor;
#endif
}

#endif // FACET_PARTICLES_INCLUDED
