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

struct Input
{
    half2   uv_MainTex  : TEXCOORD0;
    fixed4  color       : COLOR;      // r = ao, g = hue variation amount, a = billboard fade
#ifdef EFFECT_BACKSIDE_NORMALS
    fixed   facing      : VFACE;
#endif
};

sampler2D _MainTex;
fixed4 _Color;
int _TwoSided;

#ifdef EFFECT_BUMP
    sampler2D _BumpMap;
#endif

#ifdef EFFECT_EXTRA_TEX
    sampler2D _ExtraTex;   // r = smoothness, g = metallic, b = ao
#else
    half _Glossiness;
    half _Metallic;
#endif

#ifdef EFFECT_HUE_VARIATION
    half4 _HueVariationColor;
#endif

#ifdef EFFECT_BILLBOARD
    half _BillboardShadowFade;
#endif

#ifdef EFFECT_SUBSURFACE
    sampler2D _SubsurfaceTex;
    fixed4 _SubsurfaceColor;
    half _SubsurfaceIndirect;
#endif

// Geometry type stored per vertex in texcoord3.w (+2 for the second leaf group).
#define GEOM_TYPE_BRANCH 0
#define GEOM_TYPE_FROND 1
#define GEOM_TYPE_LEAF 2
#define GEOM_TYPE_FACINGLEAF 3

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
half4 LightingSpeedTreeSubsurface(inout SurfaceOutputStandard s, half3 viewDir, UnityGI gi)
{
#ifdef EFFECT_SUBSURFACE
    half roughness = 0.7 - s.Smoothness * 0.5;
    half through = GGXTerm(clamp(-dot(gi.light.dir, viewDir), 0, 1), roughness);
    s.Emission *= gi.indirect.diffuse * _SubsurfaceIndirect + gi.light.color * through;
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

void SpeedTreeSurf(Input i, inout SurfaceOutputStandard o)
{
    fixed4 color = tex2D(_MainTex, i.uv_MainTex) * _Color;

    o.Alpha = color.a * i.color.a;
    clip(o.Alpha - 0.3333);

    o.Albedo = color.rgb;
#ifdef EFFECT_HUE_VARIATION
    {
        // shift towards the hue colour, keeping the brightest channel half-way
        half3 shifted = lerp(o.Albedo, _HueVariationColor.rgb, i.color.g);
        half maxBase = max(o.Albedo.r, max(o.Albedo.g, o.Albedo.b));
        half maxShifted = max(shifted.r, max(shifted.g, shifted.b));
        shifted *= (maxBase / maxShifted) * 0.5f + 0.5f;
        o.Albedo = saturate(shifted);
    }
#endif

#ifdef EFFECT_BUMP
    o.Normal = UnpackNormal(tex2D(_BumpMap, i.uv_MainTex));
#elif defined(EFFECT_BACKSIDE_NORMALS) || defined(EFFECT_BILLBOARD)
    o.Normal = float3(0, 0, 1);
#endif

#ifdef EFFECT_BACKSIDE_NORMALS
    if (i.facing < 0.5)
        o.Normal.z = -o.Normal.z;   // two-sided leaves: light the back face from behind
#endif

#ifdef EFFECT_BILLBOARD
    o.Normal.z *= 0.5;   // flatter billboard normals match the 3D tree's GI better
    o.Normal = normalize(o.Normal);
#endif

#ifdef EFFECT_EXTRA_TEX
    fixed4 extra = tex2D(_ExtraTex, i.uv_MainTex);
    o.Smoothness = extra.r;
    o.Metallic = extra.g;
    o.Occlusion = extra.b * i.color.r;
#else
    o.Smoothness = _Glossiness;
    o.Metallic = _Metallic;
    o.Occlusion = i.color.r;
#endif

#ifdef EFFECT_SUBSURFACE
    o.Emission = tex2D(_SubsurfaceTex, i.uv_MainTex).rgb * _SubsurfaceColor.rgb;
#endif
}

#endif // SPEEDTREE8_COMMON_INCLUDED
