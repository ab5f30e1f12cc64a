// facet's SpeedTree helpers shared by the SpeedTree 8 and 9 shaders of
// Unity 6 (Unity's SpeedTreeShaderLibrary.cginc names): billboard seam
// cross-fading, camera-facing leaf cards and the wind direction in object
// space.
#ifndef SPEEDTREE_LIBRARY_INCLUDED
#define SPEEDTREE_LIBRARY_INCLUDED

#include "UnityCG.cginc"

// Billboard meshes hold several slices (and a top-down card, texcoord.z >
// 0.5). Each fades by how squarely it faces the viewer (alpha in v.color.a:
// (N.V)^4 + 0.18, or + 0.38 for the top card); slices below 1/3 collapse to
// the origin so they cost no overdraw. The normal is bent towards the camera
// so neighbouring slices light alike (no visible seams).
void BillboardSeamCrossfade(inout appdata_full v, float3 treePos)
{
    bool topDown = v.texcoord.z > 0.5;
    float3 viewDir = UNITY_MATRIX_IT_MV[2].xyz;   // the view's z axis in object space
    float3 cameraDir = normalize(mul((float3x3)unity_WorldToObject, _WorldSpaceCameraPos - treePos));
    float facing = max(dot(viewDir, v.normal), dot(cameraDir, v.normal));
    facing *= facing;
    facing *= facing;
    facing += topDown ? 0.38 : 0.18;
    v.color = float4(1, 1, 1, saturate(facing));

    if (facing < 0.3333)
        v.vertex.xyz = float3(0, 0, 0);

    if (topDown)
    {
        v.normal += cameraDir;
    }
    else
    {
        float3 binormal = cross(v.normal, v.tangent.xyz) * v.tangent.w;
        float3 right = cross(cameraDir, binormal);
        v.normal = cross(binormal, right);
    }
    v.normal = normalize(v.normal);
}

// Turns a leaf card about its anchor to face the camera. The card's offset
// is stored Z-up (rotated -90 degrees about x here), then taken from view
// space to object space without the object's rotation and scale, with the
// object's scale put back so scaled trees keep their leaf size; the offset
// keeps its length.
float3 DoLeafFacing(float3 vPos, float3 anchor)
{
    float3 offset = vPos - anchor;
    float len = length(offset);
    offset = float3(offset.x, -offset.z, offset.y);

    // the lengths of the model matrix's first three columns (glslang has no
    // matrix swizzles such as ._m00_m10_m20)
    float4x4 m = UNITY_MATRIX_M;
    float3 scale = float3(length(float3(m[0][0], m[1][0], m[2][0])),
                          length(float3(m[0][1], m[1][1], m[2][1])),
                          length(float3(m[0][2], m[1][2], m[2][2])));
    float3x3 viewToObject = mul((float3x3)unity_WorldToObject, (float3x3)UNITY_MATRIX_I_V);
    viewToObject[0] *= scale.x;
    viewToObject[1] *= scale.y;
    viewToObject[2] *= scale.z;

    offset = normalize(mul(viewToObject, offset)) * len;
    return offset + anchor;
}

// The world-space wind direction in object space, normalised. With uniform
// scaling (the default) the transpose of the model matrix's rotation is its
// inverse up to scale, which normalising removes.
#ifndef SPEEDTREE_SUPPORT_NON_UNIFORM_SCALING
#define SPEEDTREE_SUPPORT_NON_UNIFORM_SCALING 0
#endif
float3 TransformWindVectorFromWorldToLocalSpace(float3 vWindDirection)
{
#if SPEEDTREE_SUPPORT_NON_UNIFORM_SCALING
    float3 localWind = mul((float3x3)UNITY_MATRIX_I_M, vWindDirection);
#else
    float3 localWind = mul(vWindDirection, (float3x3)UNITY_MATRIX_M);
#endif
    float len = length(localWind);
    return len > 1e-5 ? localWind / len : localWind;
}

#endif // SPEEDTREE_LIBRARY_INCLUDED
