// facet's SpeedTree 7 vertex processing (Unity's SpeedTreeVertex.cginc
// names): the SpeedTreeVB vertex layout, smooth LOD, camera-facing leaves
// and the wind, selected by the GEOM_TYPE_* keyword of the mesh part.
#ifndef SPEEDTREE_VERTEX_INCLUDED
#define SPEEDTREE_VERTEX_INCLUDED

// Texcoord layout of SpeedTree 7 meshes:
//            branches                        fronds                    leaves
// 0  (xy)    diffuse uv, zw branch wind      same                      same
// 1          lod position xyz                lod position xyz          anchor xyz, w lod scalar
// 2          detail/seam uv, seam amount     frond wind xyz            leaf wind xyz, w leaf group
// 3 (xy)     -                               -                         lod position yz (with 1.w as x)
// (The semantics give the locations; half is float in facet.)
struct SpeedTreeVB
{
    float4 vertex : POSITION;
    float4 color : COLOR;      // r = ambient occlusion, a = 0 for camera-facing leaves
    float3 normal : NORMAL;
    float4 tangent : TANGENT;
    float4 texcoord : TEXCOORD0;
    float4 texcoord1 : TEXCOORD1;
    float4 texcoord2 : TEXCOORD2;
    float2 texcoord3 : TEXCOORD3;
    UNITY_VERTEX_INPUT_INSTANCE_ID
};

#ifdef ENABLE_WIND

// _WindQuality's values (the material's choice), from none to the palm model.
#define WIND_QUALITY_PALM       5
#define WIND_QUALITY_BEST       4
#define WIND_QUALITY_BETTER     3
#define WIND_QUALITY_FAST       2
#define WIND_QUALITY_FASTEST    1
#define WIND_QUALITY_NONE       0

uniform half _WindEnabled;   // set by Unity 5.x-2019 engines; facet decides from the wind vector (below)
uniform half _WindQuality;   // material: one of WIND_QUALITY_*

#ifndef SPEEDTREE_8_WIND
#define SPEEDTREE_8_WIND 1   // SpeedTree 7 uses the 7/8 wind model
#endif
#include "SpeedTreeWind.cginc"

// Wind is on when the engine gives a wind vector (what Unity 6 checks; the
// older engines' _WindEnabled flag is not needed then).
inline half FacetSpeedTreeWindQuality()
{
    return dot(_ST_WindVector.xyz, _ST_WindVector.xyz) > 0.0 ? _WindQuality : WIND_QUALITY_NONE;
}

#endif

// lodValue is the LOD cross-fade (unity_LODFade.x): with LOD_FADE_PERCENTAGE
// vertices move towards their position in the next LOD.
void OffsetSpeedTreeVertex(inout SpeedTreeVB data, float lodValue)
{
    float3 pos = data.vertex.xyz;

#ifdef ENABLE_WIND
    half windQuality = FacetSpeedTreeWindQuality();
    float3 rotatedWindVector = 0, rotatedBranchAnchor = 0;
    if (windQuality > WIND_QUALITY_NONE)
    {
        // world -> object for directions (uniform scale): v * M
        rotatedWindVector = normalize(mul(_ST_WindVector.xyz, (float3x3)unity_ObjectToWorld));
        rotatedBranchAnchor = normalize(mul(_ST_WindBranchAnchor.xyz, (float3x3)unity_ObjectToWorld)) * _ST_WindBranchAnchor.w;
    }
#endif

#if defined(GEOM_TYPE_BRANCH) || defined(GEOM_TYPE_FROND)
    #ifdef LOD_FADE_PERCENTAGE
        pos = lerp(pos, data.texcoord1.xyz, lodValue);
    #endif
    #if defined(ENABLE_WIND) && defined(GEOM_TYPE_FROND)
        if (windQuality == WIND_QUALITY_PALM)
            pos = RippleFrond(pos, data.normal, data.texcoord.x, data.texcoord.y, data.texcoord2.x, data.texcoord2.y, data.texcoord2.z);
    #endif

#elif defined(GEOM_TYPE_LEAF)
    float3 anchor = data.texcoord1.xyz;
    pos -= anchor;
    if (data.color.a == 0)
    {
        // camera-facing leaf: the offset is in view space; turn it into
        // object space (inverse of MV for directions), keeping its length
        #ifdef LOD_FADE_PERCENTAGE
            pos *= lerp(1.0, data.texcoord1.w, lodValue);
        #endif
        float len = length(pos);
        pos = normalize(mul(pos, (float3x3)UNITY_MATRIX_IT_MV)) * len;
    }
    else
    {
        #ifdef LOD_FADE_PERCENTAGE
            pos = lerp(pos, float3(data.texcoord1.w, data.texcoord3.x, data.texcoord3.y), lodValue);
        #endif
    }
    #ifdef ENABLE_WIND
        if (windQuality > WIND_QUALITY_FASTEST && windQuality < WIND_QUALITY_PALM)
        {
            float trigOffset = data.texcoord1.x + data.texcoord1.y;
            pos = LeafWind(windQuality == WIND_QUALITY_BEST, data.texcoord2.w > 0.0, pos, data.normal,
                           data.texcoord2.x, float3(0, 0, 0), data.texcoord2.y, data.texcoord2.z,
                           trigOffset, rotatedWindVector);
        }
    #endif
    pos += anchor;
#endif

#ifdef ENABLE_WIND
    float3 treePos = float3(unity_ObjectToWorld[0].w, unity_ObjectToWorld[1].w, unity_ObjectToWorld[2].w);
    #ifndef GEOM_TYPE_MESH
        if (windQuality >= WIND_QUALITY_BETTER)
            pos = BranchWind(windQuality == WIND_QUALITY_PALM, pos, treePos, float4(data.texcoord.zw, 0, 0),
                             rotatedWindVector, rotatedBranchAnchor);
    #endif
    if (windQuality > WIND_QUALITY_NONE)
        pos = GlobalWind(pos, treePos, true, rotatedWindVector, _ST_WindGlobal.x);
#endif

    data.vertex.xyz = pos;
}

#endif // SPEEDTREE_VERTEX_INCLUDED
