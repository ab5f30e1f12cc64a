// The Standard particle shaders: the surface program (vert + surf over
// SurfaceOutputStandard) and the unlit one (vertParticleUnlit /
// fragParticleUnlit). Keywords: _REQUIRE_UV2 (flipbook blending), EFFECT_BUMP
// (distortion through _GrabTexture), SOFTPARTICLES_ON with _FADING_ON (soft
// particles against _CameraDepthTexture), _FADING_ON (camera fade),
// _COLOROVERLAY_ON / _COLORCOLOR_ON / _COLORADDSUBDIFF_ON, _ALPHATEST_ON,
// _ALPHABLEND_ON, _ALPHAPREMULTIPLY_ON, _ALPHAMODULATE_ON, _NORMALMAP,
// _EMISSION, _METALLICGLOSSMAP. The maths is in FacetParticles.hlsl.
#ifndef UNITY_STANDARD_PARTICLES_INCLUDED
#define UNITY_STANDARD_PARTICLES_INCLUDED

#if _REQUIRE_UV2
#define _FLIPBOOK_BLENDING 1
#endif
#if EFFECT_BUMP
#define _DISTORTION_ON 1
#endif

#include "UnityPBSLighting.cginc"
#include "UnityStandardParticleInstancing.cginc"
#include "FacetParticles.hlsl"

struct appdata_particles
{
    float4 vertex : POSITION;
    float3 normal : NORMAL;
    fixed4 color : COLOR;
#if defined(_FLIPBOOK_BLENDING)
    float4 texcoords : TEXCOORD0;     // xy: this frame, zw: the next
    float texcoordBlend : TEXCOORD1;
#else
    float2 texcoords : TEXCOORD0;
#endif
#if defined(_NORMALMAP)
    float4 tangent : TANGENT;
#endif
    UNITY_VERTEX_INPUT_INSTANCE_ID
};

// The surface program's input.
struct Input
{
    float4 color : COLOR;
    float2 texcoord;
#if defined(_FLIPBOOK_BLENDING)
    float3 texcoord2AndBlend;
#endif
#if defined(SOFTPARTICLES_ON) || defined(_FADING_ON)
    float4 projectedPosition;         // screen position, eye depth in z
#endif
#if _DISTORTION_ON
    float4 grabPassPosition;
#endif
};

// The unlit program's interpolators.
struct VertexOutput
{
    float4 vertex : SV_POSITION;
    float4 color : COLOR;
    UNITY_FOG_COORDS(0)
    float2 texcoord : TEXCOORD1;
#if defined(_FLIPBOOK_BLENDING)
    float3 texcoord2AndBlend : TEXCOORD2;
#endif
#if defined(SOFTPARTICLES_ON) || defined(_FADING_ON)
    float4 projectedPosition : TEXCOORD3;
#endif
#if _DISTORTION_ON
    float4 grabPassPosition : TEXCOORD4;
#endif
    UNITY_VERTEX_OUTPUT_STEREO
};

sampler2D _MainTex;
float4 _MainTex_ST;
half4 _Color;
sampler2D _BumpMap;
half _BumpScale;
sampler2D _EmissionMap;
half3 _EmissionColor;
sampler2D _MetallicGlossMap;
half _Metallic;
half _Glossiness;
UNITY_DECLARE_DEPTH_TEXTURE(_CameraDepthTexture);
float4 _SoftParticleFadeParams;   // x = near fade, y = 1 / fade distance
float4 _CameraFadeParams;         // x = near fade, y = 1 / fade distance
half _Cutoff;
int _DstBlend;
#if _DISTORTION_ON
sampler2D _GrabTexture;
half _DistortionStrengthScaled;
half _DistortionBlend;
#endif
#if defined(_COLORADDSUBDIFF_ON)
half4 _ColorAddSubDiff;
#else
#define _ColorAddSubDiff half4(0, 0, 0, 0)
#endif

#define SOFT_PARTICLE_NEAR_FADE _SoftParticleFadeParams.x
#define SOFT_PARTICLE_INV_FADE_DISTANCE _SoftParticleFadeParams.y
#define CAMERA_NEAR_FADE _CameraFadeParams.x
#define CAMERA_INV_FADE_DISTANCE _CameraFadeParams.y

fixed4 readTexture(sampler2D tex, Input input)
{
#ifdef _FLIPBOOK_BLENDING
    return FacetFlipbookSample(tex, input.texcoord, input.texcoord2AndBlend.xy, input.texcoord2AndBlend.z);
#else
    return tex2D(tex, input.texcoord);
#endif
}
fixed4 readTexture(sampler2D tex, VertexOutput input)
{
#ifdef _FLIPBOOK_BLENDING
    return FacetFlipbookSample(tex, input.texcoord, input.texcoord2AndBlend.xy, input.texcoord2AndBlend.z);
#else
    return tex2D(tex, input.texcoord);
#endif
}

#if defined(_COLORCOLOR_ON)
half3 RGBtoHSV(half3 arg1) { return FacetRgbToHsv(arg1); }
half3 HSVtoRGB(half3 arg1) { return FacetHsvToRgb(arg1); }
#endif

// Vertex-stage pieces, shared by both programs (`clipPosition` in scope).
#if defined(_FLIPBOOK_BLENDING)
#define vertTexcoord(v, o) \
    o.texcoord = v.texcoords.xy; o.texcoord2AndBlend = float3(v.texcoords.zw, v.texcoordBlend);
#else
#define vertTexcoord(v, o) o.texcoord = TRANSFORM_TEX(v.texcoords.xy, _MainTex);
#endif
#define vertColor(c)
#if defined(SOFTPARTICLES_ON) || defined(_FADING_ON)
#define vertFading(o) o.projectedPosition = ComputeScreenPos(clipPosition); COMPUTE_EYEDEPTH(o.projectedPosition.z);
#else
#define vertFading(o)
#endif
#if _DISTORTION_ON
#define vertDistortion(o) o.grabPassPosition = ComputeGrabScreenPos(clipPosition);
#else
#define vertDistortion(o)
#endif

// Fragment-stage pieces (`albedo` in scope; they declare softParticlesFade
// and cameraFade). Premultiplied alpha fades the whole colour, else alpha.
#if defined(_ALPHAPREMULTIPLY_ON)
#define ALBEDO_MUL albedo
#else
#define ALBEDO_MUL albedo.a
#endif
#define fragColorMode(i) albedo = FacetParticleColorMode(albedo, i.color, _ColorAddSubDiff);
#if defined(SOFTPARTICLES_ON) && defined(_FADING_ON)
#define fragSoftParticles(i) \
    float softParticlesFade = FacetSoftParticleFade( \
        LinearEyeDepth(SAMPLE_DEPTH_TEXTURE_PROJ(_CameraDepthTexture, UNITY_PROJ_COORD(i.projectedPosition))), \
        i.projectedPosition.z, SOFT_PARTICLE_NEAR_FADE, SOFT_PARTICLE_INV_FADE_DISTANCE); \
    ALBEDO_MUL *= softParticlesFade;
#else
#define fragSoftParticles(i) float softParticlesFade = 1.0;
#endif
#if defined(_FADING_ON)
#define fragCameraFading(i) \
    float cameraFade = FacetCameraFade(i.projectedPosition.z, CAMERA_NEAR_FADE, CAMERA_INV_FADE_DISTANCE); \
    ALBEDO_MUL *= cameraFade;
#else
#define fragCameraFading(i) float cameraFade = 1.0;
#endif
// Distortion: the grab pass seen through the normal's xy, mixed by alpha.
#if _DISTORTION_ON
#define fragDistortion(i) \
    { \
        float4 grabUV = UNITY_PROJ_COORD(i.grabPassPosition); \
        grabUV.xy += normal.xy * _DistortionStrengthScaled * albedo.a; \
        albedo.rgb = lerp(tex2Dproj(_GrabTexture, grabUV).rgb, albedo.rgb, saturate(albedo.a - _DistortionBlend)); \
    }
#else
#define fragDistortion(i)
#endif

void vert(inout appdata_particles v, out Input o)
{
    UNITY_INITIALIZE_OUTPUT(Input, o);
    float4 clipPosition = UnityObjectToClipPos(v.vertex);
    vertColor(v.color);
    vertTexcoord(v, o);
    vertFading(o);
    vertDistortion(o);
}

void surf(Input input, inout SurfaceOutputStandard o)
{
    half4 albedo = readTexture(_MainTex, input) * _Color;
    fragColorMode(input);
    fragSoftParticles(input);
    fragCameraFading(input);
#if defined(_METALLICGLOSSMAP)
    fixed2 metallicGloss = readTexture(_MetallicGlossMap, input).ra * fixed2(1.0, _Glossiness);
#else
    fixed2 metallicGloss = fixed2(_Metallic, _Glossiness);
#endif
#if defined(_NORMALMAP)
    float3 normal = normalize(UnpackScaleNormal(readTexture(_BumpMap, input), _BumpScale));
#else
    float3 normal = float3(0, 0, 1);
#endif
#if defined(_EMISSION)
    half3 emission = readTexture(_EmissionMap, input).rgb * cameraFade * softParticlesFade;
#else
    half3 emission = 0;
#endif
    fragDistortion(input);

    o.Albedo = albedo.rgb;
#if defined(_NORMALMAP)
    o.Normal = normal;
#endif
    o.Emission = emission * _EmissionColor;
    o.Metallic = metallicGloss.r;
    o.Smoothness = metallicGloss.g;
#if defined(_ALPHABLEND_ON) || defined(_ALPHAPREMULTIPLY_ON) || defined(_ALPHAOVERLAY_ON)
    o.Alpha = albedo.a;
#else
    o.Alpha = 1;
#endif
#if defined(_ALPHAMODULATE_ON)
    o.Albedo = lerp(half3(1, 1, 1), albedo.rgb, albedo.a);
#endif
#if defined(_ALPHATEST_ON)
    clip(albedo.a - _Cutoff + 0.0001);
#endif
}

void vertParticleUnlit(appdata_particles v, out VertexOutput o)
{
    UNITY_SETUP_INSTANCE_ID(v);
    UNITY_INITIALIZE_OUTPUT(VertexOutput, o);
    UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO(o);
    float4 clipPosition = UnityObjectToClipPos(v.vertex);
    o.vertex = clipPosition;
    o.color = v.color;
    vertColor(o.color);
    vertTexcoord(v, o);
    vertFading(o);
    vertDistortion(o);
    UNITY_TRANSFER_FOG(o, o.vertex);
}

half4 fragParticleUnlit(VertexOutput input) : SV_Target
{
    half4 albedo = readTexture(_MainTex, input) * _Color;
    fragColorMode(input);
    fragSoftParticles(input);
    fragCameraFading(input);
#if defined(_NORMALMAP)
    float3 normal = normalize(UnpackScaleNormal(readTexture(_BumpMap, input), _BumpScale));
#else
    float3 normal = float3(0, 0, 1);
#endif
#if defined(_EMISSION)
    half3 emission = readTexture(_EmissionMap, input).rgb;
#else
    half3 emission = 0;
#endif
    fragDistortion(input);

    half4 result = albedo;
#if defined(_ALPHAMODULATE_ON)
    result.rgb = lerp(half3(1, 1, 1), albedo.rgb, albedo.a);
#endif
    result.rgb += emission * _EmissionColor * cameraFade * softParticlesFade;
#if !defined(_ALPHABLEND_ON) && !defined(_ALPHAPREMULTIPLY_ON) && !defined(_ALPHAOVERLAY_ON)
    result.a = 1;
#endif
#if defined(_ALPHATEST_ON)
    clip(albedo.a - _Cutoff + 0.0001);
#endif
    // Fog: towards white for modulate, black for additive blending, else the fog colour.
#if defined(_ALPHAMODULATE_ON)
    UNITY_APPLY_FOG_COLOR(input.fogCoord, result, fixed4(1, 1, 1, 0));
#elif !defined(_ALPHATEST_ON) && defined(_ALPHABLEND_ON) && !defined(_ALPHAPREMULTIPLY_ON)
    fixed4 fogColor = _DstBlend == 1 ? fixed4(0, 0, 0, 0) : unity_FogColor;
    UNITY_APPLY_FOG_COLOR(input.fogCoord, result, fogColor);
#else
    UNITY_APPLY_FOG(input.fogCoord, result);
#endif
    return result;
}

#endif // UNITY_STANDARD_PARTICLES_INCLUDED
