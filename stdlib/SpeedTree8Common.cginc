// facet's SpeedTree 8 surface-shader library (Unity's SpeedTree8Common.cginc
// names, 2018.3 to Unity 6): the Input struct, material values, LOD and wind
// (OffsetSpeedTreeVertex), SpeedTreeVert, the SpeedTreeSubsurface lighting
// model and the surface function SpeedTreeSurf.
//
// One file for both generations of the shader: Unity 6's SpeedTree8 shader
// defines SPEEDTREE_8_WIND before including this file, the 2018/2019 one does
// not. That only changes how camera-facing leaf cards are stored (see
// FacetSpeedTree8FaceLeaf).
#ifndef SPEEDTREE8_COMMON_INCLUDED
#define SPEEDTREE8_COMMON_INCLUDED

#if defined(SPEEDTREE_8_WIND)
    #define FACET_SPEEDTREE8_LEAF_CARDS_Z_UP 1
#endif

#include "UnityCG.cginc"
#include "UnityPBSLighting.cginc"
#include "SpeedTreeShaderLibrary.cginc"

#if defined(ENABLE_WIND) && !defined(_WINDQUALITY_NONE)
    #define SPEEDTREE_Y_UP
    #ifndef SPEEDTREE_8_WIND
        #define SPEEDTREE_8_WIND 1
    #endif
    #include "SpeedTreeWind.cginc"
    float _WindEnabled;   // set by 2018/2019 engines; facet decides from the wind vector
    UNITY_INSTANCING_BUFFER_START(STWind)
        UNITY_DEFINE_INSTANCED_PROP(float, _GlobalWindTime)   // per-billboard wind time offset
    UNITY_INSTANCING_BUFFER_END(STWind)
#endif

// Material textures: colour, then the optional normal, extra (r smoothness,
// g metallic, b ao) and subsurface maps.
sampler2D _MainTex;
#ifdef EFFECT_BUMP
    sampler2D _BumpMap;
#endif
#ifdef EFFECT_EXTRA_TEX
    sampler2D _ExtraTex;
#endif
#ifdef EFFECT_SUBSURFACE
    sampler2D _SubsurfaceTex;
#endif

// Material values.
fixed4 _Color;
int _TwoSided;
#ifndef EFFECT_EXTRA_TEX
    half _Metallic;
    half _Glossiness;
#endif
#ifdef EFFECT_HUE_VARIATION
    half4 _HueVariationColor;
#endif
#ifdef EFFECT_SUBSURFACE
    fixed4 _SubsurfaceColor;
    half _SubsurfaceIndirect;
#endif
#ifdef EFFECT_BILLBOARD
    half _BillboardShadowFade;
#endif

// The surface input: vertex colour (r ao, g hue-variation amount, a
// billboard fade), the UV and, for back-side normals, the facing sign.
struct Input
{
    float4 color : COLOR;
    float2 uv_MainTex : TEXCOORD0;
#ifdef EFFECT_BACKSIDE_NORMALS
    float facing : VFACE;
#endif
};

// Geometry type stored per vertex in texcoord3.w (+2 for the second leaf
// group): branches and fronds are fixed, leaves may turn to the camera.
#define GEOM_TYPE_FACINGLEAF 3
#define GEOM_TYPE_LEAF 2
#define GEOM_TYPE_FROND 1
#define GEOM_TYPE_BRANCH 0

// Turns a camera-facing leaf card about its anchor. Unity 6 meshes store the
// card Z-up (DoLeafFacing); 2018/2019 meshes store it in view-plane axes,
// which the inverse model-view rotation takes to object space.
float3 FacetSpeedTree8FaceLeaf(float3 pos, float3 anchor)
{
#if defined(FACET_SPEEDTREE8_LEAF_CARDS_Z_UP)
    return DoLeafFacing(pos, anchor);
#else
    float3 offset = pos - anchor;
    float len = length(offset);
    return normalize(mul(offset, (float3x3)UNITY_MATRIX_IT_MV)) * len + anchor;
#endif
}

void OffsetSpeedTreeVertex(inout appdata_full data, float lodValue)
{
#if defined(LOD_FADE_PERCENTAGE) && !defined(EFFECT_BILLBOARD)
    data.vertex.xyz = lerp(data.vertex.xyz, data.texcoord2.xyz, lodValue);   // towards the next LOD
#endif

    float geometryType = (int)(data.texcoord3.w + 0.25);
    bool leafTwo = false;
    if (geometryType > GEOM_TYPE_FACINGLEAF)
    {
        geometryType -= 2;
        leafTwo = true;
    }
    float3 anchor = float3(data.texcoord1.zw, data.texcoord2.w);

#if !defined(EFFECT_BILLBOARD)
    if (geometryType == GEOM_TYPE_FACINGLEAF)
        data.vertex.xyz = FacetSpeedTree8FaceLeaf(data.vertex.xyz, anchor);
#endif

#if defined(ENABLE_WIND) && !defined(_WINDQUALITY_NONE)
    // Wind is on when the engine gives a wind vector.
    float3 windDir = TransformWindVectorFromWorldToLocalSpace(_ST_WindVector.xyz);
    if (dot(windDir, windDir) < 1e-4)
        return;
    float3 treePos = float3(unity_ObjectToWorld[0].w, unity_ObjectToWorld[1].w, unity_ObjectToWorld[2].w);
    float3 pos = data.vertex.xyz;

    #ifndef EFFECT_BILLBOARD
        #if defined(_WINDQUALITY_FAST) || defined(_WINDQUALITY_BETTER) || defined(_WINDQUALITY_BEST)
            if (geometryType > GEOM_TYPE_FROND)   // leaves
            {
                #ifdef _WINDQUALITY_BEST
                    const bool bestWind = true;
                #else
                    const bool bestWind = false;
                #endif
                pos = LeafWind(bestWind, leafTwo, pos, data.normal, data.texcoord3.x, anchor,
                               data.texcoord3.y, data.texcoord3.z, anchor.x + anchor.y, windDir);
            }
        #endif

        bool palmWind = false;
        #ifdef _WINDQUALITY_PALM
            palmWind = true;
            if (geometryType == GEOM_TYPE_FROND)
                pos = RippleFrond(pos, data.normal, data.texcoord.x, data.texcoord.y,
                                  data.texcoord3.x, data.texcoord3.y, data.texcoord3.z);
        #endif

        #if defined(_WINDQUALITY_BETTER) || defined(_WINDQUALITY_BEST) || defined(_WINDQUALITY_PALM)
            float3 branchAnchor = normalize(mul(_ST_WindBranchAnchor.xyz, (float3x3)unity_ObjectToWorld)) * _ST_WindBranchAnchor.w;
            pos = BranchWind(palmWind, pos, treePos, float4(data.texcoord.zw, 0, 0), windDir, branchAnchor);
        #endif
    #endif

    float globalWindTime = _ST_WindGlobal.x;
    #if defined(EFFECT_BILLBOARD) && defined(UNITY_INSTANCING_ENABLED)
        globalWindTime += UNITY_ACCESS_INSTANCED_PROP(STWind, _GlobalWindTime);
    #endif
    data.vertex.xyz = GlobalWind(pos, treePos, true, windDir, globalWindTime);
#endif
}

void SpeedTreeVert(inout appdata_full v)
{
    OffsetSpeedTreeVertex(v, unity_LODFade.x);

    float3 treePos = float3(unity_ObjectToWorld[0].w, unity_ObjectToWorld[1].w, unity_ObjectToWorld[2].w);
#if defined(EFFECT_BILLBOARD)
    BillboardSeamCrossfade(v, treePos);
#endif

    // colour holds (ao, ao, ao, blend); the hue variation amount goes in g
#ifdef EFFECT_HUE_VARIATION
    v.color.g = saturate(frac(treePos.x + treePos.y + treePos.z) * _HueVariationColor.a);
#endif
}

// Standard lighting plus light through the leaf: the emission slot carries
// the subsurface colour, which is lit by a GGX lobe around the direction
// facing away from the light, plus indirect diffuse.
#ifdef EFFECT_SUBSURFACE
// What reaches the viewer through the leaf: indirect diffuse scaled by
// _SubsurfaceIndirect plus the light in a GGX lobe around the backward view.
half3 FacetSpeedTree8Transmitted(half smoothness, half3 viewDir, UnityGI gi)
{
    half cosBack = clamp(-dot(gi.light.dir, viewDir), 0, 1);
    half lobe = GGXTerm(cosBack, 0.7 - smoothness * 0.5);
    return gi.indirect.diffuse * _SubsurfaceIndirect + gi.light.color * lobe;
}
#endif

half4 LightingSpeedTreeSubsurface(inout SurfaceOutputStandard s, half3 viewDir, UnityGI gi)
{
#ifdef EFFECT_SUBSURFACE
    s.Emission *= FacetSpeedTree8Transmitted(s.Smoothness, viewDir, gi);
#endif
    return LightingStandard(s, viewDir, gi);
}

void LightingSpeedTreeSubsurface_GI(inout SurfaceOutputStandard s, UnityGIInput data, inout UnityGI gi)
{
#ifdef EFFECT_BILLBOARD
    data.atten = lerp(data.atten, 1.0, _BillboardShadowFade);   // billboards' self-shadowing looks wrong
#endif
    LightingStandard_GI(s, data, gi);
}

half4 LightingSpeedTreeSubsurface_Deferred(SurfaceOutputStandard s, half3 viewDir, UnityGI gi,
                                           out half4 outGBuffer0, out half4 outGBuffer1, out half4 outGBuffer2)
{
    s.Emission = half3(0, 0, 0);   // no light in a G-buffer pass, so no subsurface
    return LightingStandard_Deferred(s, viewDir, gi, outGBuffer0, outGBuffer1, outGBuffer2);
}

// facet's helpers for SpeedTreeSurf ---------------------------------------------

// Hue variation: the albedo moved towards the hue colour by `amount`, then
// rescaled so that its brightest channel lands half-way back to the
// original's.
half3 FacetSpeedTree8HueShift(half3 albedo, half amount)
{
#ifdef EFFECT_HUE_VARIATION
    half3 tinted = lerp(albedo, _HueVariationColor.rgb, amount);
    half peakBefore = max(albedo.r, max(albedo.g, albedo.b));
    half peakAfter = max(tinted.r, max(tinted.g, tinted.b));
    tinted *= (peakBefore / peakAfter) * 0.5f + 0.5f;
    return saturate(tinted);
#else
    return albedo;
#endif
}

// The tangent-space normal: the normal map or straight up, turned for the
// back face of two-sided leaves (lit from behind), flattened for billboards
// (their GI then matches the 3D tree's).
#if defined(EFFECT_BUMP) || defined(EFFECT_BACKSIDE_NORMALS) || defined(EFFECT_BILLBOARD)
float3 FacetSpeedTree8Normal(Input i)
{
#ifdef EFFECT_BUMP
    float3 n = UnpackNormal(tex2D(_BumpMap, i.uv_MainTex));
#else
    float3 n = float3(0, 0, 1);
#endif
#ifdef EFFECT_BACKSIDE_NORMALS
    if (i.facing < 0.5)
        n.z = -n.z;
#endif
#ifdef EFFECT_BILLBOARD
    n.z *= 0.5;
    n = normalize(n);
#endif
    return n;
}
#endif

void SpeedTreeSurf(Input i, inout SurfaceOutputStandard o)
{
    fixed4 texel = tex2D(_MainTex, i.uv_MainTex) * _Color;
    o.Alpha = texel.a * i.color.a;
    clip(o.Alpha - 0.3333);   // cut-out at a third
    o.Albedo = FacetSpeedTree8HueShift(texel.rgb, i.color.g);
#if defined(EFFECT_BUMP) || defined(EFFECT_BACKSIDE_NORMALS) || defined(EFFECT_BILLBOARD)
    o.Normal = FacetSpeedTree8Normal(i);
#endif

    // Surface response from the extra map (r smoothness, g metallic, b ao)
    // or the material sliders; the vertex colour's r is baked ao either way.
#ifdef EFFECT_EXTRA_TEX
    fixed3 extra = tex2D(_ExtraTex, i.uv_MainTex).rgb;
    half3 response = half3(extra.r, extra.g, extra.b * i.color.r);
#else
    half3 response = half3(_Glossiness, _Metallic, i.color.r);
#endif
    o.Smoothness = response.x;
    o.Metallic = response.y;
    o.Occlusion = response.z;
#ifdef EFFECT_SUBSURFACE
    o.Emission = tex2D(_SubsurfaceTex, i.uv_MainTex).rgb * _SubsurfaceColor.rgb;
#endif
}

#endif // SPEEDTREE8_COMMON_INCLUDED
