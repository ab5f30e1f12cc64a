// Custom Render Texture update and initialisation programs: the standard
// vertex programs that place each update zone's quad (from SV_VertexID, six
// vertices per zone) and give the fragment program its local/global texture
// coordinates, zone index and, for cube textures, the texel's direction.
// The CustomRenderTexture* arrays and _CustomRenderTextureInfo are material
// uniforms ("$Globals") that a runtime updating custom textures fills.
#ifndef UNITY_CUSTOM_TEXTURE_INCLUDED
#define UNITY_CUSTOM_TEXTURE_INCLUDED

#include "UnityCG.cginc"

// --- What the runtime fills ----------------------------------------------------
// The texture being updated: size and face/slice, and the texture itself
// (its previous content, for double-buffered updates).
float4 _CustomRenderTextureInfo;   // width, height, depth, cube face or 3D slice
#define _CustomRenderTextureCubeFace _CustomRenderTextureInfo.w
#define _CustomRenderTexture3DSlice _CustomRenderTextureInfo.w
#define _CustomRenderTextureWidth _CustomRenderTextureInfo.x
#define _CustomRenderTextureHeight _CustomRenderTextureInfo.y
#define _CustomRenderTextureDepth _CustomRenderTextureInfo.z
samplerCUBE _SelfTextureCube;
sampler2D _SelfTexture2D;
sampler3D _SelfTexture3D;

// Up to kCustomTextureBatchSize update zones per draw.
#define kCustomTextureBatchSize 16
float4 CustomRenderTextureParameters;
#define CustomRenderTextureIs3D CustomRenderTextureParameters.z
#define CustomRenderTexture3DTexcoordW CustomRenderTextureParameters.y
#define CustomRenderTextureUpdateSpace CustomRenderTextureParameters.x  // 0 normalised, 1 pixels
float4 CustomRenderTextureCenters[kCustomTextureBatchSize];
float4 CustomRenderTextureSizesAndRotations[kCustomTextureBatchSize];  // xyz = size, w = rotation (degrees)
float CustomRenderTexturePrimitiveIDs[kCustomTextureBatchSize];

// --- Stage interfaces -----------------------------------------------------------
// The update program's: the vertex index in; the zone's uv, the texture's uv,
// the zone index and (cube textures) the texel's direction out.
struct appdata_customrendertexture
{
    uint vertexID : SV_VertexID;
};
struct v2f_customrendertexture
{
    float4 vertex : SV_POSITION;
    float3 direction : TEXCOORD3;
    float3 localTexcoord : TEXCOORD0;   // 0..1 across the update zone
    float3 globalTexcoord : TEXCOORD1;  // 0..1 across the whole texture
    uint primitiveID : TEXCOORD2;       // the update zone's index
};
// The initialisation program's: a quad with uv in, uv and direction out.
struct appdata_init_customrendertexture
{
    float2 texcoord : TEXCOORD0;
    float4 vertex : POSITION;
};
struct v2f_init_customrendertexture
{
    float4 vertex : SV_POSITION;
    float3 direction : TEXCOORD1;
    float3 texcoord : TEXCOORD0;
};

float2 CustomRenderTextureRotate2D(float2 pos, float angle)
{
    float s = sin(angle), c = cos(angle);
    return float2(pos.x * c - pos.y * s, pos.x * s + pos.y * c);
}

// The direction through a face's uv (face order +X, -X, +Y, -Y, +Z, -Z).
float3 CustomRenderTextureComputeCubeDirection(float2 globalTexcoord)
{
    float2 p = globalTexcoord * 2.0 - 1.0;
    int face = (int)_CustomRenderTextureCubeFace;
    float3 d = float3(-p.x, -p.y, -1.0);                  // -Z
    if (face == 0) d = float3(1.0, -p.y, -p.x);
    else if (face == 1) d = float3(-1.0, -p.y, p.x);
    else if (face == 2) d = float3(p.x, 1.0, p.y);
    else if (face == 3) d = float3(p.x, -1.0, -p.y);
    else if (face == 4) d = float3(p.x, -p.y, 1.0);
    return normalize(d);
}

v2f_customrendertexture CustomRenderTextureVertexShader(appdata_customrendertexture input)
{
    // Two triangles per zone; corner c of the unit quad: x = c & 1, y = c >> 1
    // (0 = top); v grows downwards (UNITY_UV_STARTS_AT_TOP).
    static const uint kCorner[6] = { 0u, 2u, 3u, 1u, 0u, 3u };
    uint zone = input.vertexID / 6u;
    uint corner = kCorner[input.vertexID % 6u];
    float2 quadUV = float2(corner & 1u, corner >> 1u);
    float2 quadPos = float2(quadUV.x * 2.0 - 1.0, 1.0 - quadUV.y * 2.0);

    float3 center = CustomRenderTextureCenters[zone].xyz;
    float3 size = CustomRenderTextureSizesAndRotations[zone].xyz;
    float rotation = radians(CustomRenderTextureSizesAndRotations[zone].w);
    if (CustomRenderTextureUpdateSpace > 0.0) {
        center.xy /= _CustomRenderTextureInfo.xy;
        size.xy /= _CustomRenderTextureInfo.xy;
    } else {
        center.z *= _CustomRenderTextureInfo.z;
        size.z *= _CustomRenderTextureInfo.z;
    }
    float2 pos = CustomRenderTextureRotate2D(quadPos * size.xy, rotation) + (center.xy * 2.0 - 1.0);
    // 3D textures: drop zones that do not cover the slice being rendered.
    if (CustomRenderTextureIs3D > 0.0) {
        int minSlice = (int)(center.z - size.z * 0.5);
        int maxSlice = minSlice + (int)size.z;
        if (_CustomRenderTexture3DSlice < minSlice || _CustomRenderTexture3DSlice >= maxSlice) pos = float2(1000.0, 1000.0);
    }

    // Clip xy to texture uv: x from -1..1 to 0..1, y flipped.
    float2 textureUV = float2(pos.x * 0.5 + 0.5, 0.5 - pos.y * 0.5);
    v2f_customrendertexture o;
    o.vertex = float4(pos, 0.0, 1.0);
    o.direction = CustomRenderTextureComputeCubeDirection(textureUV);
    o.localTexcoord = float3(quadUV, CustomRenderTexture3DTexcoordW);
    o.globalTexcoord = float3(textureUV, CustomRenderTexture3DTexcoordW);
    o.primitiveID = asuint(CustomRenderTexturePrimitiveIDs[zone]);
    return o;
}

v2f_init_customrendertexture InitCustomRenderTextureVertexShader(appdata_init_customrendertexture v)
{
    float2 uv = v.texcoord.xy;
    v2f_init_customrendertexture o;
    o.direction = CustomRenderTextureComputeCubeDirection(uv);
    o.texcoord = float3(uv, CustomRenderTexture3DTexcoordW);
    o.vertex = UnityObjectToClipPos(v.vertex);
    return o;
}

#endif // UNITY_CUSTOM_TEXTURE_INCLUDED
