// Texture stacks (Unity's virtual-texturing API for the built-in pipeline).
// facet has no virtual texturing (UNITY_VIRTUAL_TEXTURING is never set), so
// this is Unity's fallback without it: a stack declares nothing, its layers
// are the ordinary UNITY_DECLARE_TEX2D textures of the same names, and
// sampling a stack samples that texture directly (there is no tile feedback:
// the resolve output is white).
#ifndef TEXTURESTACK_include
#define TEXTURESTACK_include

#include "HLSLSupport.cginc"
#include "UnityCG.cginc"

#define VIRTUAL_TEXTURES_ACTIVE 0

#define DECLARE_STACK_CB(stackName)
#define DECLARE_STACK(stackName, layer0)
#define DECLARE_STACK2(stackName, layer0, layer1)
#define DECLARE_STACK3(stackName, layer0, layer1, layer2)
#define DECLARE_STACK4(stackName, layer0, layer1, layer2, layer3)

// Where (and at which mip) a stack is sampled.
struct StackInfo
{
    float2 uv;
    float lod;
};

StackInfo MakeStackInfo(float2 uv)
{
    StackInfo info;
    info.uv = uv;
    info.lod = 0.0;
    return info;
}

StackInfo MakeStackInfoLod(float2 uv, float lod)
{
    StackInfo info;
    info.uv = uv;
    info.lod = lod;
    return info;
}

#define PrepareStack(uv, stackName) MakeStackInfo(uv)
#define PrepareStackLod(uv, stackName, mip) MakeStackInfoLod(uv, mip)
#define SampleStack(info, textureName) UNITY_SAMPLE_TEX2D(textureName, (info).uv)
#define SampleStackLod(info, textureName) UNITY_SAMPLE_TEX2D_LOD(textureName, (info).uv, (info).lod)
#define SampleStackNormal(info, textureName, scale) UnpackNormalWithScale(SampleStack(info, textureName), scale)
#define SampleStackLodNormal(info, textureName, scale) UnpackNormalWithScale(SampleStackLod(info, textureName), scale)
#define GetResolveOutput(info) float4(1, 1, 1, 1)
#define ResolveStack(uv, stackName) float4(1, 1, 1, 1)
#define PackResolveOutput(output) (output)

#endif // TEXTURESTACK_include
