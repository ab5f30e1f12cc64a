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

// ---- ambient / probes -----------------------------------------------------------------------
// SH is sampled in every pass that adds indirect light, i.e. all but
// ForwardAdd (facet has no lightmaps, so LIGHTPROBE_SH is not required).
#if defined(UNITY_PASS_FORWARDADD) || defined(UNITY_PASS_SHADOWCASTER)
#define UNITY_SHOULD_SAMPLE_SH 0
#else
#define UNITY_SHOULD_SAMPLE_SH 1
#endif
// The reflection used when glossy reflections are off: the environment's
// average radiance, from the SH constant term (FacetGI.hlsl).
#define unity_IndirectSpecColor float4(max(float3(unity_SHAr.w, unity_SHAg.w, unity_SHAb.w), 0.0), 1.0)

// ---- parallax ---------------------------------------------------------------------------------
// UV offset along the tangent-space view direction for a height h (0..1)
// sampled from a height map, scaled by `height` (Unity's offset-limited form).
inline float2 ParallaxOffset(half h, half height, half3 viewDir)
{
    h = h * height - height / 2.0;
    float3 v = normalize(viewDir);
    v.z += 0.42;
    return h * (v.xy / v.z);
}

// ---- packing ----------------------------------------------------------------------------------
// A 0..1 float in four 8-bit channels and back.
inline float4 EncodeFloatRGBA(float v)
{
    float4 kEncodeMul = float4(1.0, 255.0, 65025.0, 16581375.0);
    float kEncodeBit = 1.0 / 255.0;
    float4 enc = kEncodeMul * v;
    enc = frac(enc);
    enc -= enc.yzww * kEncodeBit;
    return enc;
}
inline float DecodeFloatRGBA(float4 enc) { return dot(enc, float4(1.0, 1 / 255.0, 1 / 65025.0, 1 / 16581375.0)); }
inline float2 EncodeFloatRG(float v)
{
    float2 enc = frac(float2(1.0, 255.0) * v);
    enc.x -= enc.y * (1.0 / 255.0);
    return enc;
}
inline float DecodeFloatRG(float2 enc) { return dot(enc, float2(1.0, 1 / 255.0)); }

// ---- shadow casters ---------------------------------------------------------------------------
// Point-light shadows (SHADOWS_CUBE) store the distance to the light over
// its range; facet's shadow targets are float, so the value is stored as is.
float4 UnityEncodeCubeShadowDepth(float z) { return float4(z, z, z, z); }
float UnityDecodeCubeShadowDepth(float4 vals) { return vals.r; }

// Clip position of an object-space vertex pushed back along the world
// normal by unity_LightShadowBias.z (normal offset, world units), more the
// more the surface faces away from the light. Branch-free (an offset of 0
// moves nothing): lavapipe leaks JIT code on every draw of a vertex shader
// with Unity's `if (unity_LightShadowBias.z != 0)`; the sine is clamped so
// that rounding (|cos| a hair above 1) cannot make it NaN.
float4 UnityClipSpaceShadowCasterPos(float4 vertex, float3 normal)
{
    float4 wPos = mul(unity_ObjectToWorld, vertex);
    float3 wNormal = UnityObjectToWorldNormal(normal);
    float3 wLight = normalize(UnityWorldSpaceLightDir(wPos.xyz));
    float shadowCos = dot(wNormal, wLight);
    float shadowSine = sqrt(saturate(1.0 - shadowCos * shadowCos));
    wPos.xyz -= wNormal * (unity_LightShadowBias.z * shadowSine);
    return mul(UNITY_MATRIX_VP, wPos);
}
float4 UnityClipSpaceShadowCasterPos(float3 vertex, float3 normal)
{
    return UnityClipSpaceShadowCasterPos(float4(vertex, 1.0), normal);
}
// Constant depth bias: the depth (0 near .. 1 far, not reversed) moves away
// from the light by unity_LightShadowBias.x (clamped to 0..1); with .y = 1,
// casters in front of the near plane are flattened onto it so that they
// still cast.
float4 UnityApplyLinearShadowBias(float4 clipPos)
{
    clipPos.z += saturate(unity_LightShadowBias.x) * clipPos.w;
    float clamped = max(clipPos.z, UNITY_NEAR_CLIP_VALUE * clipPos.w);
    clipPos.z = lerp(clipPos.z, clamped, unity_LightShadowBias.y);
    return clipPos;
}

#if defined(SHADOWS_CUBE) && !defined(SHADOWS_CUBE_IN_DEPTH_TEX)
// Point light: distance to the light, per pixel.
#define V2F_SHADOW_CASTER_NOPOS float3 vec : TEXCOORD0;
#define TRANSFER_SHADOW_CASTER_NOPOS_LEGACY(o, opos) \
    o.vec = mul(unity_ObjectToWorld, v.vertex).xyz - _LightPositionRange.xyz; opos = UnityObjectToClipPos(v.vertex);
#define TRANSFER_SHADOW_CASTER_NOPOS(o, opos) \
    o.vec = mul(unity_ObjectToWorld, v.vertex).xyz - _LightPositionRange.xyz; opos = UnityObjectToClipPos(v.vertex);
#define SHADOW_CASTER_FRAGMENT(i) \
    return UnityEncodeCubeShadowDepth((length(i.vec) + unity_LightShadowBias.x) * _LightPositionRange.w);
#else
// Directional and spot lights: depth only.
#define V2F_SHADOW_CASTER_NOPOS
#define TRANSFER_SHADOW_CASTER_NOPOS_LEGACY(o, opos) \
    opos = UnityObjectToClipPos(v.vertex.xyz); opos = UnityApplyLinearShadowBias(opos);
#define TRANSFER_SHADOW_CASTER_NOPOS(o, opos) \
    opos = UnityClipSpaceShadowCasterPos(v.vertex, v.normal); opos = UnityApplyLinearShadowBias(opos);
#define SHADOW_CASTER_FRAGMENT(i) return 0;
#endif
// The caster's v2f members and the vertex/fragment bodies; the vertex input
// must be called v and have vertex (and normal for the _NORMALOFFSET form).
#define V2F_SHADOW_CASTER V2F_SHADOW_CASTER_NOPOS UNITY_POSITION(pos)
#define V2F_SHADOW_CASTER_NOPOS_NOFALLBACK V2F_SHADOW_CASTER_NOPOS
#define TRANSFER_SHADOW_CASTER(o) TRANSFER_SHADOW_CASTER_NOPOS_LEGACY(o, o.pos)
#define TRANSFER_SHADOW_CASTER_NORMALOFFSET(o) TRANSFER_SHADOW_CASTER_NOPOS(o, o.pos)

// ---- legacy helpers -------------------------------------------------------------------------
// Object-space tangent frame `rotation` (rows tangent, binormal, normal)
// from appdata `v`, as old vertex programs use it.
#define TANGENT_SPACE_ROTATION \
    float3 binormal = cross(normalize(v.normal), normalize(v.tangent.xyz)) * v.tangent.w; \
    float3x3 rotation = float3x3(v.tangent.xyz, binormal, v.normal)

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
