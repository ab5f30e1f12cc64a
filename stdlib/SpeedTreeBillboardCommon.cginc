// facet's SpeedTree 7 billboard library (Unity's SpeedTreeBillboardCommon.
// cginc names): expands the billboard quad around the tree's position,
// turned to the camera, picks the atlas image of the viewing angle, and
// applies the global wind.
#ifndef SPEEDTREE_BILLBOARD_COMMON_INCLUDED
#define SPEEDTREE_BILLBOARD_COMMON_INCLUDED

#define SPEEDTREE_ALPHATEST
fixed _Cutoff;

#include "SpeedTreeCommon.cginc"

// Set by the engine (loose globals, filled by name; Unity keeps them in the
// UnityBillboardPerCamera / UnityBillboardPerBatch cbuffers).
float3 unity_BillboardNormal;          // billboard plane facing the camera (xz)
float3 unity_BillboardTangent;
float4 unity_BillboardCameraParams;    // xyz = camera position, w = camera angle about y (radians)
#define unity_BillboardCameraPosition (unity_BillboardCameraParams.xyz)
#define unity_BillboardCameraXZAngle (unity_BillboardCameraParams.w)
float4 unity_BillboardInfo;            // x = number of image slices, y = 1 / angle between slices
float4 unity_BillboardSize;            // x = width, y = height, z = bottom offset
float4 unity_BillboardImageTexCoords[16];  // per slice: xy = uv origin, zw = uv extent (w < 0: rotated image)

struct SpeedTreeBillboardData
{
    float4 vertex       : POSITION;    // the tree's position (object space, no rotation or scale)
    float2 texcoord     : TEXCOORD0;   // corner of the quad, 0..1
    float4 texcoord1    : TEXCOORD1;   // x = width scale, y = height scale, z = rotation, w = wind time offset
    float3 normal       : NORMAL;
    float4 tangent      : TANGENT;
    float4 color        : COLOR;
    UNITY_VERTEX_INPUT_INSTANCE_ID
};

void SpeedTreeBillboardVert(inout SpeedTreeBillboardData v, out Input o)
{
    UNITY_INITIALIZE_OUTPUT(Input, o);

    float3 worldPos = v.vertex.xyz + float3(unity_ObjectToWorld[0].w, unity_ObjectToWorld[1].w, unity_ObjectToWorld[2].w);

#ifdef BILLBOARD_FACE_CAMERA_POS
    // Face the camera's position (not only its direction): the plane's
    // tangent is horizontal and perpendicular to the eye vector.
    float3 eyeVec = normalize(unity_BillboardCameraPosition - worldPos);
    float3 billboardTangent = normalize(float3(-eyeVec.z, 0, eyeVec.x));
    float3 billboardNormal = float3(billboardTangent.z, 0, -billboardTangent.x);
    float angle = atan2(billboardNormal.z, billboardNormal.x);
    angle += angle < 0 ? 2 * UNITY_PI : 0;
#else
    float3 billboardTangent = unity_BillboardTangent;
    float3 billboardNormal = unity_BillboardNormal;
    float angle = unity_BillboardCameraXZAngle;
#endif

    float2 percent = v.texcoord.xy;
    float3 offset = (percent.x - 0.5f) * unity_BillboardSize.x * v.texcoord1.x * billboardTangent;
    offset.y += (percent.y * unity_BillboardSize.y + unity_BillboardSize.z) * v.texcoord1.y;

#ifdef ENABLE_WIND
    if (FacetSpeedTreeWindQuality() > WIND_QUALITY_NONE)
        offset = GlobalWind(offset, worldPos, true, _ST_WindVector.xyz, v.texcoord1.w);
#endif

    v.vertex.xyz += offset;
    v.vertex.w = 1.0f;
    v.normal = billboardNormal;
    v.tangent = float4(billboardTangent, -1);

    // The atlas image whose viewing angle is nearest (plus the tree's own rotation).
    angle += v.texcoord1.z;
    int image = (int)fmod(floor(angle * unity_BillboardInfo.y + 0.5f), unity_BillboardInfo.x);
    float4 imageTexCoords = unity_BillboardImageTexCoords[image];
    o.mainTexUV = imageTexCoords.w < 0
        ? imageTexCoords.xy - imageTexCoords.zw * percent.yx   // stored rotated in the atlas
        : imageTexCoords.xy + imageTexCoords.zw * percent;

    o.color = _Color;

#ifdef EFFECT_HUE_VARIATION
    o.HueVariationAmount = saturate(frac(worldPos.x + worldPos.y + worldPos.z) * _HueVariation.a);
#endif
}

#endif // SPEEDTREE_BILLBOARD_COMMON_INCLUDED
