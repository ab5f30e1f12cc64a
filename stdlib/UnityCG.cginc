// Unity's common helpers for vertex/fragment programs, as aliases over
// FacetCore.hlsl. Each name is described in docs/stdlib.md.
#ifndef UNITY_CG_INCLUDED
#define UNITY_CG_INCLUDED

#include "UnityShaderVariables.cginc"
#include "UnityShaderUtilities.cginc"
#include "FacetCore.hlsl"

// Multiples of pi and their inverses, from the half turn up.
#define UNITY_HALF_PI 1.57079632679f
#define UNITY_INV_HALF_PI 0.636619772367f
#define UNITY_PI 3.14159265359f
#define UNITY_INV_PI 0.31830988618f
#define UNITY_TWO_PI 6.28318530718f
#define UNITY_INV_TWO_PI 0.15915494309f
#define UNITY_FOUR_PI 12.56637061436f
#define UNITY_INV_FOUR_PI 0.07957747155f
// The smallest normal 16-bit float (2^-14).
#define UNITY_HALF_MIN 6.103515625e-5

// Colour-space constants. Linear: the gamma values converted with the sRGB
// curve; the dielectric F0 is 0.04 (4% reflectance) in both spaces.
#ifndef UNITY_COLORSPACE_GAMMA
#define unity_ColorSpaceDielectricSpec half4(0.04, 0.04, 0.04, 1.0 - 0.04)
#define unity_ColorSpaceLuminance half4(0.2126729, 0.7151522, 0.0721750, 1.0)
#define unity_ColorSpaceGrey fixed4(0.214041144, 0.214041144, 0.214041144, 0.5)
#define unity_ColorSpaceDouble fixed4(4.59479380, 4.59479380, 4.59479380, 2.0)
inline bool IsGammaSpace() { return false; }
#else
#define unity_ColorSpaceDielectricSpec half4(0.220916301, 0.220916301, 0.220916301, 1.0 - 0.220916301)
#define unity_ColorSpaceLuminance half4(0.22, 0.707, 0.071, 0.0)
#define unity_ColorSpaceGrey fixed4(0.5, 0.5, 0.5, 0.5)
#define unity_ColorSpaceDouble fixed4(2.0, 2.0, 2.0, 2.0)
inline bool IsGammaSpace() { return true; }
#endif

// ---- vertex inputs ------------------------------------------------------------
// Position, normal and first UV; the tangent form adds the tangent (w: the
// binormal sign); the full form all four UV sets and the vertex colour.
// The semantics, not the member order, give the locations.
struct appdata_base
{
    float4 vertex : POSITION;
    float4 texcoord : TEXCOORD0;
    float3 normal : NORMAL;
    UNITY_VERTEX_INPUT_INSTANCE_ID
};
struct appdata_tan
{
    float4 vertex : POSITION;
    float4 texcoord : TEXCOORD0;
    float3 normal : NORMAL;
    float4 tangent : TANGENT;
    UNITY_VERTEX_INPUT_INSTANCE_ID
};
struct appdata_full
{
    float4 vertex : POSITION;
    float4 color : COLOR;
    float3 normal : NORMAL;
    float4 tangent : TANGENT;
    float4 texcoord : TEXCOORD0;
    float4 texcoord1 : TEXCOORD1;
    float4 texcoord2 : TEXCOORD2;
    float4 texcoord3 : TEXCOORD3;
    UNITY_VERTEX_INPUT_INSTANCE_ID
};
// The image-effect pair used by vert_img.
struct appdata_img
{
    float4 vertex : POSITION;
    float2 texcoord : TEXCOORD0;
    UNITY_VERTEX_INPUT_INSTANCE_ID
};
struct v2f_img
{
    float4 pos : SV_POSITION;
    float2 uv : TEXCOORD0;
    UNITY_VERTEX_INPUT_INSTANCE_ID
    UNITY_VERTEX_OUTPUT_STEREO
};
struct v2f_vertex_lit {
    float2 uv : TEXCOORD0;
    fixed4 diff : COLOR0;
    fixed4 spec : COLOR1;
};
// Legacy names: the vertex input's normal and uv (no texture matrices).
#define SCALED_NORMAL v.normal
#define TRANSFORM_UV(idx) v.texcoord.xy

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
float2 MultiplyUV(float4x4 mat, float2 inUV) { return mul(mat, float4(inUV, 0, 0)).xy; }
inline float2 TransformViewToProjection(float2 v) { return mul((float2x2)UNITY_MATRIX_P, v); }
inline float3 TransformViewToProjection(float3 v) { return mul((float3x3)UNITY_MATRIX_P, v); }

// ---- vertex lights --------------------------------------------------------------------------
// ForwardBase's four per-vertex point lights (unity_4LightPos*, zero in
// facet: no contribution) and the Vertex pass's eight lights
// (unity_LightPosition etc., view space). See FacetBuiltins.hlsl.
float3 Shade4PointLights(float4 lightPosX, float4 lightPosY, float4 lightPosZ, float3 lightColor0,
                         float3 lightColor1, float3 lightColor2, float3 lightColor3, float4 lightAttenSq,
                         float3 pos, float3 normal)
{
    return FacetShade4PointLights(lightPosX, lightPosY, lightPosZ, lightColor0, lightColor1, lightColor2,
                                  lightColor3, lightAttenSq, pos, normal);
}
// Ambient plus `lightCount` lights at an object-space vertex; spot cones
// when spotLight is true.
float3 ShadeVertexLightsFull(float4 vertex, float3 normal, int lightCount, bool spotLight)
{
    float3 viewPos = UnityObjectToViewPos(vertex.xyz);
    float3 viewNormal = normalize(mul((float3x3)UNITY_MATRIX_IT_MV, normal));
    float3 sum = UNITY_LIGHTMODEL_AMBIENT.xyz;
    for (int li = 0; li < lightCount; li++) {
        float3 toLight = unity_LightPosition[li].xyz - viewPos * unity_LightPosition[li].w;
        float distSq = max(dot(toLight, toLight), 0.000001);
        toLight *= rsqrt(distSq);
        float atten = 1.0 / (1.0 + distSq * unity_LightAtten[li].z);
        if (spotLight) {
            float rho = max(0.0, dot(toLight, unity_SpotDirection[li].xyz));
            atten *= saturate((rho - unity_LightAtten[li].x) * unity_LightAtten[li].y);
        }
        sum += unity_LightColor[li].rgb * (max(0.0, dot(viewNormal, toLight)) * atten);
    }
    return sum;
}
float3 ShadeVertexLights(float4 vertex, float3 normal) { return ShadeVertexLightsFull(vertex, normal, 4, false); }
inline fixed4 VertexLight(v2f_vertex_lit i, sampler2D mainTex)
{
    fixed4 texcol = tex2D(mainTex, i.uv);
    return fixed4(texcol.xyz * i.diff.xyz + i.spec.xyz * texcol.a, texcol.w * i.diff.w);
}

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
inline float4 ComputeNonStereoScreenPos(float4 pos) { return ComputeScreenPos(pos); }
#define V2F_SCREEN_TYPE float4
// Rounds a clip position to the nearest pixel centre grid (pixel-perfect sprites).
inline float4 UnityPixelSnap(float4 pos)
{
    float2 halfSize = _ScreenParams.xy * 0.5;
    pos.xy = round(pos.xy / pos.w * halfSize) / halfSize * pos.w;
    return pos;
}
// Single-pass stereo is off: screen-space uvs are used as they are, or
// scaled/offset explicitly by UnityStereoScreenSpaceUVAdjust.
inline float2 UnityStereoScreenSpaceUVAdjustInternal(float2 uv, float4 scaleAndOffset) { return uv * scaleAndOffset.xy + scaleAndOffset.zw; }
inline float4 UnityStereoScreenSpaceUVAdjustInternal(float4 uv, float4 scaleAndOffset)
{
    return float4(uv.xy * scaleAndOffset.xy + scaleAndOffset.zw, uv.zw * scaleAndOffset.xy + scaleAndOffset.zw);
}
#define UnityStereoScreenSpaceUVAdjust(x, y) UnityStereoScreenSpaceUVAdjustInternal(x, y)
#define TransformStereoScreenSpaceTex(uv, w) (uv)
#define UnityStereoTransformScreenSpaceTex(uv) (uv)
#define UnityStereoClamp(uv, scaleAndOffset) (uv)

// ---- depth ----------------------------------------------------------------------------
inline float Linear01Depth(float z) { return FacetLinear01Depth(z); }
inline float LinearEyeDepth(float z) { return FacetLinearEyeDepth(z); }
// UNITY_SAMPLE_DEPTH, SAMPLE_DEPTH_TEXTURE(_PROJ/_LOD): HLSLSupport.cginc.
#define COMPUTE_EYEDEPTH(o) o = -UnityObjectToViewPos(v.vertex).z
#define COMPUTE_DEPTH_01 -(UnityObjectToViewPos(v.vertex).z * _ProjectionParams.w)
#define COMPUTE_VIEW_NORMAL normalize(mul((float3x3)UNITY_MATRIX_IT_MV, v.normal))
#define DECODE_EYEDEPTH(i) LinearEyeDepth(i)
// Depth textures are native: nothing to pass or write.
#define UNITY_TRANSFER_DEPTH(oo)
#define UNITY_OUTPUT_DEPTH(i) return 0

// ---- colour ------------------------------------------------------------------------------
inline half3 GammaToLinearSpace(half3 sRGB) { return FacetSrgbToLinear(sRGB); }
inline half3 LinearToGammaSpace(half3 linRGB) { return FacetLinearToSrgb(linRGB); }
inline float GammaToLinearSpaceExact(float value) { return FacetSrgbToLinear(float3(value, value, value)).x; }
inline float LinearToGammaSpaceExact(float value) { return FacetLinearToSrgb(float3(value, value, value)).x; }
inline half Luminance(half3 rgb) { return dot(rgb, unity_ColorSpaceLuminance.rgb); }
inline half LinearRgbToLuminance(half3 linearRgb) { return FacetLuminance(linearRgb); }

// ---- textures --------------------------------------------------------------------------------
inline fixed3 UnpackNormal(fixed4 packednormal) { return FacetUnpackNormal(packednormal); }
// facet's helper: a unit-length normal from its x and y, z the positive root.
float3 FacetNormalFromXY(float2 xy) { return float3(xy, sqrt(1.0 - saturate(dot(xy, xy)))); }
// x from alpha, y from green (DXT5nm), or x from red (BC5, alpha 1): the
// product red * alpha serves both.
fixed3 UnpackNormalmapRGorAG(fixed4 packednormal)
{
    float2 encoded = float2(packednormal.x * packednormal.w, packednormal.y);
    return FacetNormalFromXY(encoded * 2.0 - 1.0);
}
inline fixed3 UnpackNormalDXT5nm(fixed4 packednormal) { return FacetNormalFromXY(packednormal.wy * 2.0 - 1.0); }
// Unity's form rebuilds z from the scaled xy in both encodings.
fixed3 UnpackNormalWithScale(fixed4 packednormal, float scale)
{
#ifndef UNITY_NO_DXT5nm
    float2 encoded = float2(packednormal.x * packednormal.w, packednormal.y);
#else
    float2 encoded = packednormal.xy;
#endif
    return FacetNormalFromXY((encoded * 2.0 - 1.0) * scale);
}
inline half3 DecodeHDR(half4 data, half4 decodeInstructions) { return FacetDecodeHDR(data, decodeInstructions); }
// Unity 6's form with the colour space as an argument: gamma skips the exponent.
inline half3 DecodeHDR(half4 data, half4 decodeInstructions, int colorspaceIsGamma)
{
    half alpha = decodeInstructions.w * (data.a - 1.0) + 1.0;
    return colorspaceIsGamma ? (decodeInstructions.x * alpha) * data.rgb : FacetDecodeHDR(data, decodeInstructions);
}
// RGBM with a maximum range: rgb / alpha with alpha quantised up to 8 bits.
half4 UnityEncodeRGBM(half3 color, float maxRGBM)
{
    float3 rgb = color / maxRGBM;
    float alpha = max(max(rgb.r, rgb.g), max(rgb.b, 0.02));
    alpha = max(ceil(alpha * 255.0) / 255.0, 0.02);
    return half4(rgb / alpha, alpha);
}

// ---- lightmaps ------------------------------------------------------------------------------
// facet's lightmaps (when a runtime provides them) are plain HDR textures:
// the decode instructions are (1, 1, 0, 0), and DecodeLightmap(c) is c.rgb
// (Unity's UNITY_LIGHTMAP_FULL_HDR). The RGBM and double-LDR forms stay
// available for shaders that call them. unity_Lightmap, unity_LightmapInd,
// unity_LightmapST etc. are in FacetBuiltins.hlsl.
#define unity_Lightmap_HDR half4(1.0, 1.0, 0.0, 0.0)
#define unity_DynamicLightmap_HDR half4(1.0, 1.0, 0.0, 0.0)
#define LIGHTMAP_RGBM_SCALE 5.0
#define EMISSIVE_RGBM_SCALE 97.0
inline half3 DecodeLightmapRGBM(half4 data, half4 decodeInstructions)
{
#if defined(UNITY_COLORSPACE_GAMMA)
    return (decodeInstructions.x * data.a) * data.rgb;
#else
    return (decodeInstructions.x * pow(max(data.a, 0.0), decodeInstructions.y)) * data.rgb;
#endif
}
inline half3 DecodeLightmapDoubleLDR(fixed4 color, half4 decodeInstructions) { return decodeInstructions.x * color.rgb; }
// The encoding the project's lightmaps use; full HDR (facet's) by default.
#if defined(UNITY_LIGHTMAP_DLDR_ENCODING)
inline half3 DecodeLightmap(fixed4 color, half4 decodeInstructions) { return DecodeLightmapDoubleLDR(color, decodeInstructions); }
#elif defined(UNITY_LIGHTMAP_RGBM_ENCODING)
inline half3 DecodeLightmap(fixed4 color, half4 decodeInstructions) { return DecodeLightmapRGBM(color, decodeInstructions); }
#else
inline half3 DecodeLightmap(fixed4 color, half4 decodeInstructions) { return color.rgb; }
#endif
inline half3 DecodeLightmap(fixed4 color) { return DecodeLightmap(color, unity_Lightmap_HDR); }
// Realtime (Enlighten) lightmaps: RGBM in linear space with its own exponent.
inline half3 DecodeRealtimeLightmap(fixed4 color)
{
    return pow(max((unity_DynamicLightmap_HDR.x * color.a) * color.rgb, 0.0), unity_DynamicLightmap_HDR.y);
}
// Directional lightmaps: half-Lambert against the baked dominant direction
// (rgb, biased by 0.5), divided by its length stored in alpha.
inline half3 DecodeDirectionalLightmap(half3 color, fixed4 dirTex, half3 normalWorld)
{
    half halfLambert = dot(normalWorld, dirTex.xyz - 0.5) + 0.5;
    return color * halfLambert / max(1e-4, dirTex.w);
}

// ---- ambient ---------------------------------------------------------------------------------
// The L0+L1 and L2 parts of the environment SH, linear, unclamped.
half3 SHEvalLinearL0L1(half4 normal) { return FacetSHEvalL0L1(normal, unity_SHAr, unity_SHAg, unity_SHAb); }
half3 SHEvalLinearL2(half4 normal) { return FacetSHEvalL2(normal, unity_SHBr, unity_SHBg, unity_SHBb, unity_SHC); }
// facet's helper: SH results come out linear; gamma projects want them
// converted.
half3 FacetShInColorSpace(half3 linearValue)
{
#ifdef UNITY_COLORSPACE_GAMMA
    return LinearToGammaSpace(linearValue);
#else
    return linearValue;
#endif
}
// Environment irradiance for a world normal (normal.w = 1), in the project's colour space.
half3 ShadeSH9(half4 normal) { return FacetShInColorSpace(FacetShadeSH9(normal)); }
// Old partial forms: only L2 (ShadeSH3Order) or only L0+L1 (ShadeSH12Order).
half3 ShadeSH3Order(half4 normal) { return FacetShInColorSpace(SHEvalLinearL2(normal)); }
half3 ShadeSH12Order(half4 normal) { return FacetShInColorSpace(SHEvalLinearL0L1(normal)); }

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
// Unity's lower-level fog names. The coordinate facet passes is the fog
// distance (FacetFogDistance), which for its 0..1 clip depth Unity's
// UNITY_Z_0_FAR_FROM_CLIPSPACE approximates by clip z as well.
#define UNITY_Z_0_FAR_FROM_CLIPSPACE(coord) (coord)
#define UNITY_CALC_FOG_FACTOR_RAW(coord) float unityFogFactor = FacetFogFactor(coord)
#define UNITY_CALC_FOG_FACTOR(coord) UNITY_CALC_FOG_FACTOR_RAW(UNITY_Z_0_FAR_FROM_CLIPSPACE(coord))
#define UNITY_FOG_LERP_COLOR(col, fogCol, fogFac) col.rgb = lerp((fogCol).rgb, (col).rgb, saturate(fogFac))
// The fog distance carried in a spare component of another interpolator
// (as Unity's generated surface passes do), then pulled out as _unity_fogCoord.
#if defined(FOG_LINEAR) || defined(FOG_EXP) || defined(FOG_EXP2)
#define UNITY_TRANSFER_FOG_COMBINED_WITH_TSPACE(o, outpos) o.tSpace2.y = FacetFogDistance(outpos)
#define UNITY_TRANSFER_FOG_COMBINED_WITH_WORLD_POS(o, outpos) o.worldPos.w = FacetFogDistance(outpos)
#define UNITY_TRANSFER_FOG_COMBINED_WITH_EYE_VEC(o, outpos) o.eyeVec.w = FacetFogDistance(outpos)
#define UNITY_EXTRACT_FOG(name) float _unity_fogCoord = name.fogCoord
#define UNITY_EXTRACT_FOG_FROM_TSPACE(name) float _unity_fogCoord = name.tSpace2.y
#define UNITY_EXTRACT_FOG_FROM_WORLD_POS(name) float _unity_fogCoord = name.worldPos.w
#define UNITY_EXTRACT_FOG_FROM_EYE_VEC(name) float _unity_fogCoord = name.eyeVec.w
#else
#define UNITY_TRANSFER_FOG_COMBINED_WITH_TSPACE(o, outpos)
#define UNITY_TRANSFER_FOG_COMBINED_WITH_WORLD_POS(o, outpos)
#define UNITY_TRANSFER_FOG_COMBINED_WITH_EYE_VEC(o, outpos)
#define UNITY_EXTRACT_FOG(name)
#define UNITY_EXTRACT_FOG_FROM_TSPACE(name)
#define UNITY_EXTRACT_FOG_FROM_WORLD_POS(name)
#define UNITY_EXTRACT_FOG_FROM_EYE_VEC(name)
#endif

// ---- tangent frames packed in three interpolators (tSpace0..2) ------------------------------
// Rows of the tangent-to-world matrix as _unity_tbn_0..2; UNITY_RECONSTRUCT_TBN
// rebuilds them from tangent and normal (the binormal sign in tSpace1.y)
// when the generated pass packs other data in the spare components.
// facet's helper: component `axis` of three vectors, as one vector (a row
// of the matrix whose columns they are).
float3 FacetFrameRow(float3 c0, float3 c1, float3 c2, int axis) { return float3(c0[axis], c1[axis], c2[axis]); }
#define UNITY_EXTRACT_TBN_0(name) fixed3 _unity_tbn_0 = name.tSpace0.xyz
#define UNITY_RECONSTRUCT_TBN_0 fixed3 _unity_tbn_0 = FacetFrameRow(_unity_tangent, _unity_binormal, _unity_normal, 0)
#define UNITY_EXTRACT_TBN_1(name) fixed3 _unity_tbn_1 = name.tSpace1.xyz
#define UNITY_RECONSTRUCT_TBN_1 fixed3 _unity_tbn_1 = FacetFrameRow(_unity_tangent, _unity_binormal, _unity_normal, 1)
#define UNITY_EXTRACT_TBN_2(name) fixed3 _unity_tbn_2 = name.tSpace2.xyz
#define UNITY_RECONSTRUCT_TBN_2 fixed3 _unity_tbn_2 = FacetFrameRow(_unity_tangent, _unity_binormal, _unity_normal, 2)
#define UNITY_EXTRACT_TBN(name) UNITY_EXTRACT_TBN_0(name); UNITY_EXTRACT_TBN_1(name); UNITY_EXTRACT_TBN_2(name)
// Tangent and normal are the x and z columns; the binormal is rebuilt and
// its sign taken from tSpace1.y.
#define UNITY_EXTRACT_TBN_T(name) fixed3 _unity_tangent = FacetFrameRow(name.tSpace0.xyz, name.tSpace1.xyz, name.tSpace2.xyz, 0)
#define UNITY_EXTRACT_TBN_N(name) fixed3 _unity_normal = FacetFrameRow(name.tSpace0.xyz, name.tSpace1.xyz, name.tSpace2.xyz, 2)
#define UNITY_EXTRACT_TBN_B(name) fixed3 _unity_binormal = cross(_unity_normal, _unity_tangent)
#define UNITY_CORRECT_TBN_B_SIGN(name) _unity_binormal *= name.tSpace1.y;
#if defined(FOG_LINEAR) || defined(FOG_EXP) || defined(FOG_EXP2)
#define UNITY_RECONSTRUCT_TBN(name) UNITY_EXTRACT_TBN_T(name); UNITY_EXTRACT_TBN_N(name); UNITY_EXTRACT_TBN_B(name); \
    UNITY_CORRECT_TBN_B_SIGN(name); UNITY_RECONSTRUCT_TBN_0; UNITY_RECONSTRUCT_TBN_1; UNITY_RECONSTRUCT_TBN_2
#else
#define UNITY_RECONSTRUCT_TBN(name) UNITY_EXTRACT_TBN(name)
#endif

// ---- LOD cross-fade -------------------------------------------------------------------------
// LOD_FADE_CROSSFADE: discard by a 4x4 screen-space dither against
// unity_LODFade.x (negative: fading in). facet computes the Bayer pattern
// instead of sampling Unity's unity_DitherMask texture.
#define UNITY_DITHER_CROSSFADE_COORDS
#define UNITY_DITHER_CROSSFADE_COORDS_IDX(idx)
#define UNITY_TRANSFER_DITHER_CROSSFADE(o, v)
#define UNITY_TRANSFER_DITHER_CROSSFADE_HPOS(o, hpos)
void UnityApplyDitherCrossFade(float2 vpos)
{
    float mask = FacetDitherThreshold(vpos);
    float sgn = unity_LODFade.x > 0 ? 1.0 : -1.0;
    clip(unity_LODFade.x - mask * sgn);
}
#ifdef LOD_FADE_CROSSFADE
#define UNITY_APPLY_DITHER_CROSSFADE(vpos) UnityApplyDitherCrossFade(vpos)
#else
#define UNITY_APPLY_DITHER_CROSSFADE(vpos)
#endif

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
    // Each channel keeps the fraction of v scaled by a further 255, less
    // what the next channel carries.
    float4 digits = frac(float4(1.0, 255.0, 65025.0, 16581375.0) * v);
    return digits - digits.yzww * (1.0 / 255.0);
}
inline float DecodeFloatRGBA(float4 enc) { return dot(enc, float4(1.0, 1 / 255.0, 1 / 65025.0, 1 / 16581375.0)); }
inline float2 EncodeFloatRG(float v)
{
    float2 enc = frac(float2(1.0, 255.0) * v);
    enc.x -= enc.y * (1.0 / 255.0);
    return enc;
}
inline float DecodeFloatRG(float2 enc) { return dot(enc, float2(1.0, 1 / 255.0)); }
// View-space normals in two 0..1 channels (FacetEncodeViewNormal), and the
// depth-normals layout: normal in xy, 0..1 depth in zw.
inline float2 EncodeViewNormalStereo(float3 n) { return FacetEncodeViewNormal(n); }
inline float3 DecodeViewNormalStereo(float4 enc4) { return FacetDecodeViewNormal(enc4.xy); }
inline float4 EncodeDepthNormal(float depth, float3 normal) { return float4(EncodeViewNormalStereo(normal), EncodeFloatRG(depth)); }
inline void DecodeDepthNormal(float4 enc, out float depth, out float3 normal)
{
    depth = DecodeFloatRG(enc.zw);
    normal = DecodeViewNormalStereo(enc);
}
// Heightmaps: facet's targets have 16-bit red, so the height is stored as is.
float4 PackHeightmap(float height) { return float4(height, height, height, height); }
float UnpackHeightmap(float4 height) { return height.r; }

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
#define V2F_SHADOW_CASTER_NOPOS_IS_EMPTY
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
