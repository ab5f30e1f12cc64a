// facet's SpeedTree 7 surface-shader library (Unity's SpeedTreeCommon.cginc
// names): the Input struct, material values, the vertex function
// SpeedTreeVert and the fragment helper SpeedTreeFrag (diffuse, detail
// blend, hue variation, normal map).
#ifndef SPEEDTREE_COMMON_INCLUDED
#define SPEEDTREE_COMMON_INCLUDED

#include "UnityCG.cginc"

#define SPEEDTREE_Y_UP

#ifdef GEOM_TYPE_BRANCH_DETAIL
    #define GEOM_TYPE_BRANCH
#endif

#include "SpeedTreeVertex.cginc"

// --- Material values ---------------------------------------------------------
fixed4 _Color;
sampler2D _MainTex;
#ifdef GEOM_TYPE_BRANCH_DETAIL
    sampler2D _DetailTex;
#endif
#if defined(EFFECT_BUMP) && !defined(LIGHTMAP_ON)
    sampler2D _BumpMap;
#endif
#ifdef EFFECT_HUE_VARIATION
    half4 _HueVariation;   // rgb = target hue, a = strength
#endif
// Fronds and leaves are alpha tested. (SpeedTreeBillboardCommon.cginc
// defines SPEEDTREE_ALPHATEST and _Cutoff itself before including this.)
#if !defined(SPEEDTREE_ALPHATEST) && (defined(GEOM_TYPE_FROND) || defined(GEOM_TYPE_LEAF) || defined(GEOM_TYPE_FACING_LEAF))
    #define SPEEDTREE_ALPHATEST
    fixed _Cutoff;
#endif

// --- The surface input ---------------------------------------------------------
// Vertex colour (ambient occlusion times _Color), the main uv with the hue
// variation amount, and for detailed branches the detail uv with the blend
// (0..1, or 2.5 for "use the detail's alpha"); the macros name the parts.
struct Input
{
    float3 interpolator1;
#ifdef GEOM_TYPE_BRANCH_DETAIL
    float3 interpolator2;
#endif
    float4 color;
};
#define mainTexUV interpolator1.xy
#ifdef EFFECT_HUE_VARIATION
    #define HueVariationAmount interpolator1.z
#endif
#ifdef GEOM_TYPE_BRANCH_DETAIL
    #define Detail interpolator2
#endif

#ifdef EFFECT_HUE_VARIATION
// How far this vertex moves towards the hue colour: mostly per tree (from
// its position), plus a little per vertex.
float FacetSpeedTreeHueAmount(float3 vertex, float3 normal)
{
    float3 treePos = float3(unity_ObjectToWorld[0].w, unity_ObjectToWorld[1].w, unity_ObjectToWorld[2].w);
    float perTree = frac(treePos.x + treePos.y + treePos.z);
    float amount = perTree + (frac(vertex.x + normal.y + normal.x) * 0.5 - 0.3);
    return saturate(amount * _HueVariation.a);
}
#endif

void SpeedTreeVert(inout SpeedTreeVB v, out Input o)
{
    UNITY_INITIALIZE_OUTPUT(Input, o);
    o.color = float4(_Color.rgb * v.color.r, _Color.a);   // r: ambient occlusion
    o.mainTexUV = v.texcoord.xy;
#ifdef EFFECT_HUE_VARIATION
    o.HueVariationAmount = FacetSpeedTreeHueAmount(v.vertex.xyz, v.normal);
#endif
#ifdef GEOM_TYPE_BRANCH_DETAIL
    // Seam blending (alpha 0) and detail texturing use separate parts of the
    // mesh, so the two meanings of .z never interpolate into each other.
    float blend = v.color.a == 0 ? v.texcoord2.z : 2.5f;
    o.Detail = float3(v.texcoord2.xy, blend);
#endif
    OffsetSpeedTreeVertex(v, unity_LODFade.x);
}

// --- The fragment part ---------------------------------------------------------
// SpeedTreeFrag's result, copied into the surface output by
// SPEEDTREE_COPY_FRAG; the normal only with EFFECT_BUMP.
#ifndef EFFECT_BUMP
    #define SPEEDTREE_DATA_NORMAL
    #define SPEEDTREE_COPY_NORMAL(to, from)
#else
    #define SPEEDTREE_DATA_NORMAL fixed3 Normal;
    #define SPEEDTREE_COPY_NORMAL(to, from) to.Normal = from.Normal;
#endif
#define SPEEDTREE_COPY_FRAG(to, from) to.Alpha = from.Alpha; to.Albedo = from.Albedo; SPEEDTREE_COPY_NORMAL(to, from)
struct SpeedTreeFragOut
{
    fixed Alpha;
    fixed3 Albedo;
    SPEEDTREE_DATA_NORMAL
};

// Shifts a colour towards the hue variation colour while keeping its
// brightest channel roughly where it was (half-way), so it stays vivid.
inline half3 FacetSpeedTreeHueShift(half3 color, half3 hue, half amount)
{
    half3 shifted = lerp(color, hue, amount);
    half maxBase = max(color.r, max(color.g, color.b));
    half maxShifted = max(shifted.r, max(shifted.g, shifted.b));
    shifted *= (maxBase / maxShifted) * 0.5f + 0.5f;
    return saturate(shifted);
}

#ifdef GEOM_TYPE_BRANCH_DETAIL
// The detail layer's share at this pixel: the interpolated blend, or (2.5
// marks it) the detail texture's own alpha.
half FacetSpeedTreeDetailBlend(float blendOrMarker, half detailAlpha)
{
    return blendOrMarker < 2.0f ? saturate(blendOrMarker) : detailAlpha;
}
#endif

void SpeedTreeFrag(Input i, out SpeedTreeFragOut o)
{
    half4 texel = tex2D(_MainTex, i.mainTexUV);
    o.Alpha = texel.a * _Color.a;
#ifdef SPEEDTREE_ALPHATEST
    clip(o.Alpha - _Cutoff);
#endif

    half3 albedo = texel.rgb;
#ifdef GEOM_TYPE_BRANCH_DETAIL
    half4 detailTexel = tex2D(_DetailTex, i.Detail.xy);
    half detailShare = FacetSpeedTreeDetailBlend(i.Detail.z, detailTexel.a);
    albedo = lerp(albedo, detailTexel.rgb, detailShare);
#endif
#ifdef EFFECT_HUE_VARIATION
    albedo = FacetSpeedTreeHueShift(albedo, _HueVariation.rgb, i.HueVariationAmount);
#endif
    o.Albedo = albedo * i.color.rgb;

    // Lightmapped trees keep the flat normal the lightmap was baked with.
#if defined(EFFECT_BUMP) && defined(LIGHTMAP_ON)
    o.Normal = fixed3(0, 0, 1);
#elif defined(EFFECT_BUMP) && defined(GEOM_TYPE_BRANCH_DETAIL)
    o.Normal = lerp(UnpackNormal(tex2D(_BumpMap, i.mainTexUV)), UnpackNormal(tex2D(_BumpMap, i.Detail.xy)), detailShare);
#elif defined(EFFECT_BUMP)
    o.Normal = UnpackNormal(tex2D(_BumpMap, i.mainTexUV));
#endif
}

#endif // SPEEDTREE_COMMON_INCLUDED
