// The deferred G-buffer layout of Unity's built-in pipeline (facet renders
// forward; this keeps deferred passes compiling and gives the same layout):
//   RT0 = (diffuse colour, occlusion), RT1 = (specular colour, smoothness),
//   RT2 = (world normal * 0.5 + 0.5, 1).
#ifndef UNITY_GBUFFER_INCLUDED
#define UNITY_GBUFFER_INCLUDED

struct UnityStandardData
{
    half3 diffuseColor;
    half occlusion;
    half3 specularColor;
    half smoothness;
    float3 normalWorld;
};

void UnityStandardDataToGbuffer(UnityStandardData data, out half4 outGBuffer0, out half4 outGBuffer1, out half4 outGBuffer2)
{
    outGBuffer0 = half4(data.diffuseColor, data.occlusion);
    outGBuffer1 = half4(data.specularColor, data.smoothness);
    outGBuffer2 = half4(data.normalWorld * 0.5 + 0.5, 1.0);
}

UnityStandardData UnityStandardDataFromGbuffer(half4 inGBuffer0, half4 inGBuffer1, half4 inGBuffer2)
{
    UnityStandardData data;
    data.diffuseColor = inGBuffer0.rgb;
    data.occlusion = inGBuffer0.a;
    data.specularColor = inGBuffer1.rgb;
    data.smoothness = inGBuffer1.a;
    data.normalWorld = normalize((float3)inGBuffer2.rgb * 2.0 - 1.0);
    return data;
}

// Scales what a decal-like pass writes by its coverage alpha.
void UnityStandardDataApplyWeightToGbuffer(inout half4 inOutGBuffer0, inout half4 inOutGBuffer1, inout half4 inOutGBuffer2,
                                           half alpha)
{
    inOutGBuffer0.rgb *= alpha;
    inOutGBuffer1 *= alpha;
    inOutGBuffer2.rgb *= alpha;
}

#endif // UNITY_GBUFFER_INCLUDED
