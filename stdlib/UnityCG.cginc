// Unity's common helpers for vertex/fragment programs, as aliases over
// FacetCore.hlsl. Each name is described in docs/stdlib.md.
#ifndef UNITY_CG_INCLUDED
#define UNITY_CG_INCLUDED

#include "UnityShaderVariables.cginc"
#include "UnityShaderUtilities.cginc"
#include "FacetCore.hlsl"

#define UNITY_PI 3.14159265359f
#define UNITY_TWO_PI 6.28318530718f
#define UNITY_FOUR_PI 12.56637061436f
#define UNITY_INV_PI 0.31830988618f
#define UNITY_INV_TWO_PI 0.15915494309f
#define UNITY_INV_FOUR_PI 0.07957747155f
#define UNITY_HALF_PI 1.57079632679f
#define UNITY_INV_HALF_PI 0.636619772367f

// Colour-space constants. Linear: the gamma values converted with the sRGB
// curve; the dielectric F0 is 0.04 (4% reflectance) in both spaces.
#ifdef UNITY_COLORSPACE_GAMMA
#define unity_ColorSpaceGrey fixed4(0.5, 0.5, 0.5, 0.5)
#define unity_ColorSpaceDouble fixed4(2.0, 2.0, 2.0, 2.0)
#define unity_ColorSpaceDielectricSpec half4(0.220916301, 0.220916301, 0.220916301, 1.0 - 0.220916301)
#define unity_ColorSpaceLuminance half4(0.22, 0.707, 0.071, 0.0)
#else
#define unity_ColorSpaceGrey fixed4(0.214041144, 0.214041144, 0.214041144, 0.5)
#define unity_ColorSpaceDouble fixed4(4.59479380, 4.59479380, 4.59479380, 2.0)
#define unity_ColorSpaceDielectricSpec half4(0.04, 0.04, 0.04, 1.0 - 0.04)
#define unity_ColorSpaceLuminance half4(0.2126729, 0.7151522, 0.0721750, 1.0)
#endif

// ---- vertex inputs ------------------------------------------------------------
struct appdata_base {
    float4 vertex : POSITION;
    float3 normal : NORMAL;
    float4 texcoord : TEXCOORD0;
    UNITY_VERTEX_INPUT_INSTANCE_ID
};
struct appdata_tan {
    float4 vertex : POSITION;
    float4 tangent : TANGENT;
    float3 normal : NORMAL;
    float4 texcoord : TEXCOORD0;
    UNITY_VERTEX_INPUT_INSTANCE_ID
};
struct appdata_full {
    float4 vertex : POSITION;
    float4 tangent : TANGENT;
    float3 normal : NORMAL;
    float4 texcoord : TEXCOORD0;
    float4 texcoord1 : TEXCOORD1;
    float4 texcoord2 : TEXCOORD2;
    float4 texcoord3 : TEXCOORD3;
    fixed4 color : COLOR;
    UNITY_VERTEX_INPUT_INSTANCE_ID
};
struct appdata_img {
    float4 vertex : POSITION;
    half2 texcoord : TEXCOORD0;
    UNITY_VERTEX_INPUT_INSTANCE_ID
};
struct v2f_img {
    float4 pos : SV_POSITION;
    half2 uv : TEXCOORD0;
};

// ---- transforms ------------------------------------------------------------------
inline float4 UnityWorldToClipPos(in float3 pos) { return FacetWorldToClipPos(pos); }
inline float4 UnityViewToClipPos(in float3 pos) { return FacetViewToClipPos(pos); }
inline float3 UnityObjectToViewPos(in float3 pos) { return FacetObjectToViewPos(pos); }
inline float3 UnityObjectToViewPos(float4 pos) { return FacetObjectToViewPos(pos.xyz); }
inline float3 UnityWorldToViewPos(in float3 pos) { return FacetWorldToViewPos(pos); }
inline float3 UnityObjectToWorldDir(in float3 dir) { return FacetObjectToWorldDir(dir); }
inline float3 UnityWorldToObjectDir(in float3 dir) { return FacetWorldToObjectDir(dir); }
inline float3 UnityObjectToWorldNormal(in float3 norm) { return FacetObjectToWorldNormal(norm); }
inline float3 UnityWorldSpaceViewDir(in float3 worldPos) { return FacetWorldViewDir(worldPos); }
inline float3 UnityWorldSpaceLightDir(in float3 worldPos) { return FacetWorldLightDir(worldPos); }
// Object-space position in, world-space direction out (not normalised).
inline float3 WorldSpaceViewDir(in float4 localPos) { return FacetWorldViewDir(FacetObjectToWorldPos(localPos.xyz)); }
inline float3 WorldSpaceLightDir(in float4 localPos) { return FacetWorldLightDir(FacetObjectToWorldPos(localPos.xyz)); }
// Object-space position in, object-space direction out (not normalised).
inline float3 ObjSpaceViewDir(in float4 v)
{
    float3 objSpaceCameraPos = mul(unity_WorldToObject, float4(_WorldSpaceCameraPos.xyz, 1.0)).xyz;
    return objSpaceCameraPos - v.xyz;
}
inline float3 ObjSpaceLightDir(in float4 v)
{
    float3 objSpaceLightPos = mul(unity_WorldToObject, _WorldSpaceLightPos0).xyz;
    return objSpaceLightPos - v.xyz * _WorldSpaceLightPos0.w;
}

#define TRANSFORM_TEX(tex, name) (tex.xy * name##_ST.xy + name##_ST.zw)

// ---- screen space -------------------------------------------------------------------
// xy / w is the 0..1 screen position (0 at the top-left in Vulkan).
inline float4 ComputeScreenPos(float4 pos)
{
    float4 o = pos * 0.5f;
    o.xy = float2(o.x, o.y * _ProjectionParams.x) + o.w;
    o.zw = pos.zw;
    return o;
}
inline float4 ComputeGrabScreenPos(float4 pos) { return ComputeScreenPos(pos); }

// ---- depth ----------------------------------------------------------------------------
inline float Linear01Depth(float z) { return FacetLinear01Depth(z); }
inline float LinearEyeDepth(float z) { return FacetLinearEyeDepth(z); }
#define UNITY_SAMPLE_DEPTH(value) (value).r
#define SAMPLE_DEPTH_TEXTURE(tex, uv) (tex2D(tex, uv).r)
#define SAMPLE_DEPTH_TEXTURE_PROJ(tex, uv) (tex2Dproj(tex, uv).r)
#define SAMPLE_DEPTH_TEXTURE_LOD(tex, uv) (tex2Dlod(tex, uv).r)
#define COMPUTE_EYEDEPTH(o) o = -UnityObjectToViewPos(v.vertex).z
#define COMPUTE_DEPTH_01 -(UnityObjectToViewPos(v.vertex).z * _ProjectionParams.w)

// ---- colour ------------------------------------------------------------------------------
inline half3 GammaToLinearSpace(half3 sRGB) { return FacetSrgbToLinear(sRGB); }
inline half3 LinearToGammaSpace(half3 linRGB) { return FacetLinearToSrgb(linRGB); }
inline float GammaToLinearSpaceExact(float value) { return FacetSrgbToLinear(float3(value, value, value)).x; }
inline float LinearToGammaSpaceExact(float value) { return FacetLinearToSrgb(float3(value, value, value)).x; }
inline half Luminance(half3 rgb) { return dot(rgb, unity_ColorSpaceLuminance.rgb); }
inline half LinearRgbToLuminance(half3 linearRgb) { return FacetLuminance(linearRgb); }

// ---- textures --------------------------------------------------------------------------------
inline fixed3 UnpackNormal(fixed4 packednormal) { return FacetUnpackNormal(packednormal); }
inline half3 DecodeHDR(half4 data, half4 decodeInstructions) { return FacetDecodeHDR(data, decodeInstructions); }

// ---- ambient ---------------------------------------------------------------------------------
// Environment irradiance for a world normal (normal.w = 1), in the project's colour space.
half3 ShadeSH9(half4 normal)
{
    half3 res = FacetShadeSH9(normal);
#ifdef UNITY_COLORSPACE_GAMMA
    res = LinearToGammaSpace(res);
#endif
    return res;
}

// ---- fog (keywords FOG_LINEAR, FOG_EXP, FOG_EXP2 from multi_compile_fog) -----------------------
#if defined(FOG_LINEAR) || defined(FOG_EXP) || defined(FOG_EXP2)
#define UNITY_FOG_COORDS(idx) float1 fogCoord : TEXCOORD##idx;
#define UNITY_TRANSFER_FOG(o, outpos) o.fogCoord = FacetWithFogDistance(o.fogCoord, FacetFogDistance(outpos))
#define UNITY_APPLY_FOG_COLOR(coord, col, fogCol) col.rgb = lerp((fogCol).rgb, (col).rgb, FacetFogFactor((coord).x))
#else
#define UNITY_FOG_COORDS(idx)
#define UNITY_TRANSFER_FOG(o, outpos)
#define UNITY_APPLY_FOG_COLOR(coord, col, fogCol)
#endif
// The fog distance in .x of a wider interpolator whose other components the shader uses.
#define UNITY_FOG_COORDS_PACKED(idx, vectype) vectype fogCoord : TEXCOORD##idx;
// Additive passes fade towards black so that fog is not added once per light.
#ifdef UNITY_PASS_FORWARDADD
#define UNITY_APPLY_FOG(coord, col) UNITY_APPLY_FOG_COLOR(coord, col, fixed4(0, 0, 0, 0))
#else
#define UNITY_APPLY_FOG(coord, col) UNITY_APPLY_FOG_COLOR(coord, col, unity_FogColor)
#endif

#define UNITY_OPAQUE_ALPHA(outputAlpha) outputAlpha = 1.0

// ---- image effects ----------------------------------------------------------------------------
v2f_img vert_img(appdata_img v)
{
    v2f_img o;
    UNITY_INITIALIZE_OUTPUT(v2f_img, o);
    o.pos = UnityObjectToClipPos(v.vertex);
    o.uv = v.texcoord;
    return o;
}

#endif // UNITY_CG_INCLUDED
