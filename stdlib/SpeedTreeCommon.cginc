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

struct Input
{
    fixed4 color;
    half3 interpolator1;   // xy = main uv, z = hue variation amount
#ifdef GEOM_TYPE_BRANCH_DETAIL
    half3 interpolator2;   // xy = detail uv, z = blend (0..1) or 2.5 for "use the detail's alpha"
#endif
};

#define mainTexUV interpolator1.xy
sampler2D _MainTex;

#ifdef GEOM_TYPE_BRANCH_DETAIL
    #define Detail interpolator2
    sampler2D _DetailTex;
#endif

// Fronds and leaves are alpha tested. (SpeedTreeBillboardCommon.cginc
// defines SPEEDTREE_ALPHATEST and _Cutoff itself before including this.)
#if (defined(GEOM_TYPE_FROND) || defined(GEOM_TYPE_LEAF) || defined(GEOM_TYPE_FACING_LEAF)) && !defined(SPEEDTREE_ALPHATEST)
    #define SPEEDTREE_ALPHATEST
    fixed _Cutoff;
#endif

#ifdef EFFECT_HUE_VARIATION
    #define HueVariationAmount interpolator1.z
    half4 _HueVariation;   // rgb = target hue, a = strength
#endif

#if defined(EFFECT_BUMP) && !defined(LIGHTMAP_ON)
    sampler2D _BumpMap;
#endif

fixed4 _Color;

void SpeedTreeVert(inout SpeedTreeVB v, out Input o)
{
    UNITY_INITIALIZE_OUTPUT(Input, o);

    o.mainTexUV = v.texcoord.xy;
    o.color = _Color;
    o.color.rgb *= v.color.r;   // ambient occlusion

#ifdef EFFECT_HUE_VARIATION
    // per tree (its position) plus a little per vertex
    float3 treePos = float3(unity_ObjectToWorld[0].w, unity_ObjectToWorld[1].w, unity_ObjectToWorld[2].w);
    float amount = frac(treePos.x + treePos.y + treePos.z);
    amount += frac(v.vertex.x + v.normal.y + v.normal.x) * 0.5 - 0.3;
    o.HueVariationAmount = saturate(amount * _HueVariation.a);
#endif

#ifdef GEOM_TYPE_BRANCH_DETAIL
    // Seam blending (alpha 0) and detail texturing use separate parts of the
    // mesh, so the two meanings of .z never interpolate into each other.
    o.Detail.xy = v.texcoord2.xy;
    o.Detail.z = v.color.a == 0 ? v.texcoord2.z : 2.5f;
#endif

    OffsetSpeedTreeVertex(v, unity_LODFade.x);
}

#if defined(EFFECT_BUMP)
    #define SPEEDTREE_DATA_NORMAL           fixed3 Normal;
    #define SPEEDTREE_COPY_NORMAL(to, from) to.Normal = from.Normal;
#else
    #define SPEEDTREE_DATA_NORMAL
    #define SPEEDTREE_COPY_NORMAL(to, from)
#endif

#define SPEEDTREE_COPY_FRAG(to, from)   \
    to.Albedo = from.Albedo;            \
    to.Alpha = from.Alpha;              \
    SPEEDTREE_COPY_NORMAL(to, from)

struct SpeedTreeFragOut
{
    fixed3 Albedo;
    fixed Alpha;
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

void SpeedTreeFrag(Input i, out SpeedTreeFragOut o)
{
    half4 diffuse = tex2D(_MainTex, i.mainTexUV);

    o.Alpha = diffuse.a * _Color.a;
#ifdef SPEEDTREE_ALPHATEST
    clip(o.Alpha - _Cutoff);
#endif

#ifdef GEOM_TYPE_BRANCH_DETAIL
    half4 detail = tex2D(_DetailTex, i.Detail.xy);
    half detailBlend = i.Detail.z < 2.0f ? saturate(i.Detail.z) : detail.a;
    diffuse.rgb = lerp(diffuse.rgb, detail.rgb, detailBlend);
#endif

#ifdef EFFECT_HUE_VARIATION
    diffuse.rgb = FacetSpeedTreeHueShift(diffuse.rgb, _HueVariation.rgb, i.HueVariationAmount);
#endif

    o.Albedo = diffuse.rgb * i.color.rgb;

#if defined(EFFECT_BUMP)
    #if defined(LIGHTMAP_ON)
        o.Normal = fixed3(0, 0, 1);
    #else
        o.Normal = UnpackNormal(tex2D(_BumpMap, i.mainTexUV));
        #ifdef GEOM_TYPE_BRANCH_DETAIL
            o.Normal = lerp(o.Normal, UnpackNormal(tex2D(_BumpMap, i.Detail.xy)), detailBlend);
        #endif
    #endif
#endif
}

#endif // SPEEDTREE_COMMON_INCLUDED
