// The Standard particle shaders: the surface program (vert + surf over
// SurfaceOutputStandard) and the unlit one (vertParticleUnlit /
// fragParticleUnlit). Keywords: _REQUIRE_UV2 (flipbook blending), EFFECT_BUMP
// (distortion through _GrabTexture), SOFTPARTICLES_ON with _FADING_ON (soft
// particles against _CameraDepthTexture), _FADING_ON (camera fade),
// _COLOROVERLAY_ON / _COLORCOLOR_ON / _COLORADDSUBDIFF_ON, _ALPHATEST_ON,
// _ALPHABLEND_ON, _ALPHAPREMULTIPLY_ON, _ALPHAMODULATE_ON, _NORMALMAP,
// _EMISSION, _METALLICGLOSSMAP. The maths is in FacetParticles.hlsl; the
// Facet* functions below tie it to this file's properties.
#ifndef UNITY_STANDARD_PARTICLES_INCLUDED
#define UNITY_STANDARD_PARTICLES_INCLUDED

// The material keywords switch on the internal feature names.
#ifdef _REQUIRE_UV2
#define _FLIPBOOK_BLENDING 1
#endif
#ifdef EFFECT_BUMP
#define _DISTORTION_ON 1
#endif

#include "UnityPBSLighting.cginc"
#include "UnityStandardParticleInstancing.cginc"
#include "FacetParticles.hlsl"

// Mesh data of a particle (half and fixed are float in facet; the semantics
// fix the locations, not the member order).
struct appdata_particles
{
    float4 vertex : POSITION;
    float4 color : COLOR;
    float3 normal : NORMAL;
#ifdef _NORMALMAP
    float4 tangent : TANGENT;
#endif
#ifdef _FLIPBOOK_BLENDING
    float4 texcoords : TEXCOORD0;     // this frame in xy, the next one in zw
    float texcoordBlend : TEXCOORD1;
#else
    float2 texcoords : TEXCOORD0;
#endif
    UNITY_VERTEX_INPUT_INSTANCE_ID
};

// --- Properties ---------------------------------------------------------------

// Colour, alpha cut-off and the blend factor the fog choice looks at.
sampler2D _MainTex;
float4 _MainTex_ST;
half4 _Color;
half _Cutoff;
int _DstBlend;
#if defined(_COLORADDSUBDIFF_ON)
half4 _ColorAddSubDiff;
#else
#define _ColorAddSubDiff half4(0, 0, 0, 0)
#endif

// Lit surface: normal, emission, metallic and smoothness.
sampler2D _BumpMap;
half _BumpScale;
sampler2D _MetallicGlossMap;
half _Metallic;
half _Glossiness;
sampler2D _EmissionMap;
half3 _EmissionColor;

// Refraction of what lies behind (EFFECT_BUMP).
#if _DISTORTION_ON
sampler2D _GrabTexture;
half _DistortionStrengthScaled;
half _DistortionBlend;
#endif

// Fading near the scene and near the camera: x near distance, y inverse
// length of the ramp.
UNITY_DECLARE_DEPTH_TEXTURE(_CameraDepthTexture);
float4 _SoftParticleFadeParams;
float4 _CameraFadeParams;
#define SOFT_PARTICLE_NEAR_FADE _SoftParticleFadeParams.x
#define SOFT_PARTICLE_INV_FADE_DISTANCE _SoftParticleFadeParams.y
#define CAMERA_NEAR_FADE _CameraFadeParams.x
#define CAMERA_INV_FADE_DISTANCE _CameraFadeParams.y

// --- facet's particle helpers ----------------------------------------------

// One read of a particle texture: the current frame, blended with the next
// one (frames.xy, weight frames.z) when flipbook blending is on.
float4 FacetParticleRead(sampler2D tex, float2 uv, float3 frames)
{
#ifdef _FLIPBOOK_BLENDING
    return FacetFlipbookSample(tex, uv, frames.xy, frames.z);
#else
    return tex2D(tex, uv);
#endif
}

// Screen position for the fades, with the eye depth of `objectPos` in z.
float4 FacetParticleProjectedPosition(float4 clipPos, float4 objectPos)
{
    float4 projected = ComputeScreenPos(clipPos);
    projected.z = -UnityObjectToViewPos(objectPos).z;
    return projected;
}

// Scales what a fade acts on: the whole colour under premultiplied alpha,
// only alpha otherwise.
// (ALBEDO_MUL names that part for code written against Unity's file.)
#if defined(_ALPHAPREMULTIPLY_ON)
#define ALBEDO_MUL albedo
#else
#define ALBEDO_MUL albedo.a
#endif
void FacetParticleFade(inout half4 albedo, float fade) { ALBEDO_MUL *= fade; }

float FacetParticleSoftFade(float4 projected)
{
    float sceneDepth = LinearEyeDepth(SAMPLE_DEPTH_TEXTURE_PROJ(_CameraDepthTexture, UNITY_PROJ_COORD(projected)));
    return FacetSoftParticleFade(sceneDepth, projected.z, SOFT_PARTICLE_NEAR_FADE, SOFT_PARTICLE_INV_FADE_DISTANCE);
}

float FacetParticleCameraFade(float4 projected)
{
    return FacetCameraFade(projected.z, CAMERA_NEAR_FADE, CAMERA_INV_FADE_DISTANCE);
}

// The colour behind the particle, looked up through the normal's xy
// (stronger where the particle is opaque) and mixed with the albedo.
#if _DISTORTION_ON
half3 FacetParticleDistort(half4 albedo, float3 normal, float4 grabPosition)
{
    float4 uv = UNITY_PROJ_COORD(grabPosition);
    uv.xy += normal.xy * _DistortionStrengthScaled * albedo.a;
    half3 behind = tex2Dproj(_GrabTexture, uv).rgb;
    return lerp(behind, albedo.rgb, saturate(albedo.a - _DistortionBlend));
}
#endif

// Alpha as written out: kept by the blended modes, 1 for opaque ones.
half FacetParticleOutputAlpha(half alpha)
{
#if defined(_ALPHABLEND_ON) || defined(_ALPHAPREMULTIPLY_ON) || defined(_ALPHAOVERLAY_ON)
    return alpha;
#else
    return 1;
#endif
}

void FacetParticleAlphaTest(half alpha)
{
#if defined(_ALPHATEST_ON)
    clip(alpha - _Cutoff + 0.0001);
#endif
}

// Multiplicative blending: the albedo faded towards white by (1 - alpha).
half3 FacetParticleModulate(half4 albedo) { return lerp(half3(1, 1, 1), albedo.rgb, albedo.a); }

// The tangent-space normal of the normal map, or straight up without one.
#if defined(_NORMALMAP)
#define FacetParticleNormal(input) normalize(UnpackScaleNormal(readTexture(_BumpMap, input), _BumpScale))
#else
#define FacetParticleNormal(input) float3(0, 0, 1)
#endif

// --- Unity's particle pieces, on top of the helpers -------------------------

#if defined(_COLORCOLOR_ON)
half3 RGBtoHSV(half3 arg1) { return FacetRgbToHsv(arg1); }
half3 HSVtoRGB(half3 arg1) { return FacetHsvToRgb(arg1); }
#endif

// Vertex stage (`v`, `o` and `clipPosition` in scope).
#define vertColor(c)
#if defined(_FLIPBOOK_BLENDING)
#define vertTexcoord(v, o) o.texcoord = v.texcoords.xy; o.texcoord2AndBlend = float3(v.texcoords.zw, v.texcoordBlend);
#else
#define vertTexcoord(v, o) o.texcoord = TRANSFORM_TEX(v.texcoords.xy, _MainTex);
#endif
#if defined(SOFTPARTICLES_ON) || defined(_FADING_ON)
#define vertFading(o) o.projectedPosition = FacetParticleProjectedPosition(clipPosition, v.vertex);
#else
#define vertFading(o)
#endif
#if _DISTORTION_ON
#define vertDistortion(o) o.grabPassPosition = ComputeGrabScreenPos(clipPosition);
#else
#define vertDistortion(o)
#endif
// Everything both vertex programs fill in alike (the colour stays in the mesh
// for the surface program).
#define FacetParticleVertexShared(v, o) vertTexcoord(v, o) vertFading(o) vertDistortion(o)

// Fragment stage (`albedo` in scope; the fades declare softParticlesFade
// and cameraFade, 1 where they are off).
#define fragColorMode(i) albedo = FacetParticleColorMode(albedo, i.color, _ColorAddSubDiff);
#if defined(SOFTPARTICLES_ON) && defined(_FADING_ON)
#define fragSoftParticles(i) float softParticlesFade = FacetParticleSoftFade(i.projectedPosition); FacetParticleFade(albedo, softParticlesFade);
#else
#define fragSoftParticles(i) float softParticlesFade = 1.0;
#endif
#if defined(_FADING_ON)
#define fragCameraFading(i) float cameraFade = FacetParticleCameraFade(i.projectedPosition); FacetParticleFade(albedo, cameraFade);
#else
#define fragCameraFading(i) float cameraFade = 1.0;
#endif
#if _DISTORTION_ON
#define fragDistortion(i) albedo.rgb = FacetParticleDistort(albedo, normal, i.grabPassPosition);
#else
#define fragDistortion(i)
#endif

// --- The surface program ---------------------------------------------------------

// What surf reads: UV and colour, plus the second flipbook frame, the
// projected position of the fades and the grab-pass position where on.
struct Input
{
    float2 texcoord;
    float4 color : COLOR;
#ifdef _FLIPBOOK_BLENDING
    float3 texcoord2AndBlend;
#endif
#if _DISTORTION_ON
    float4 grabPassPosition;
#endif
#if defined(SOFTPARTICLES_ON) || defined(_FADING_ON)
    float4 projectedPosition;         // eye depth in z
#endif
};

#if defined(_FLIPBOOK_BLENDING)
fixed4 readTexture(sampler2D tex, Input input) { return FacetParticleRead(tex, input.texcoord, input.texcoord2AndBlend); }
#else
fixed4 readTexture(sampler2D tex, Input input) { return FacetParticleRead(tex, input.texcoord, 0); }
#endif

void vert(inout appdata_particles v, out Input o)
{
    UNITY_INITIALIZE_OUTPUT(Input, o);
    float4 clipPosition = UnityObjectToClipPos(v.vertex);
    FacetParticleVertexShared(v, o);
}

void surf(Input input, inout SurfaceOutputStandard o)
{
    half4 albedo = readTexture(_MainTex, input) * _Color;
    fragColorMode(input);
    fragSoftParticles(input);
    fragCameraFading(input);
    float3 normal = FacetParticleNormal(input);
    fragDistortion(input);

#if defined(_METALLICGLOSSMAP)
    half2 surface = readTexture(_MetallicGlossMap, input).ra * half2(1.0, _Glossiness);
#else
    half2 surface = half2(_Metallic, _Glossiness);
#endif
    o.Metallic = surface.x;
    o.Smoothness = surface.y;
#if defined(_NORMALMAP)
    o.Normal = normal;
#endif
#if defined(_EMISSION)
    o.Emission = readTexture(_EmissionMap, input).rgb * cameraFade * softParticlesFade * _EmissionColor;
#else
    o.Emission = 0;
#endif
#if defined(_ALPHAMODULATE_ON)
    o.Albedo = FacetParticleModulate(albedo);
#else
    o.Albedo = albedo.rgb;
#endif
    o.Alpha = FacetParticleOutputAlpha(albedo.a);
    FacetParticleAlphaTest(albedo.a);
}

// --- The unlit program ----------------------------------------------------------

// The unlit program's interpolators (the same optional members as Input).
struct VertexOutput
{
    float4 vertex : SV_POSITION;
    float2 texcoord : TEXCOORD1;
    float4 color : COLOR;
#ifdef _FLIPBOOK_BLENDING
    float3 texcoord2AndBlend : TEXCOORD2;
#endif
#if _DISTORTION_ON
    float4 grabPassPosition : TEXCOORD4;
#endif
#if defined(SOFTPARTICLES_ON) || defined(_FADING_ON)
    float4 projectedPosition : TEXCOORD3;
#endif
    UNITY_FOG_COORDS(0)
    UNITY_VERTEX_OUTPUT_STEREO
};

#if defined(_FLIPBOOK_BLENDING)
fixed4 readTexture(sampler2D tex, VertexOutput input) { return FacetParticleRead(tex, input.texcoord, input.texcoord2AndBlend); }
#else
fixed4 readTexture(sampler2D tex, VertexOutput input) { return FacetParticleRead(tex, input.texcoord, 0); }
#endif

// The fog colour of the unlit program: white for multiplicative blending,
// black for additive (one-one) blending, the scene's fog colour otherwise.
#if defined(_ALPHAMODULATE_ON)
#define FacetParticleApplyFog(fogCoord, color) UNITY_APPLY_FOG_COLOR(fogCoord, color, fixed4(1, 1, 1, 0))
#elif !defined(_ALPHATEST_ON) && defined(_ALPHABLEND_ON) && !defined(_ALPHAPREMULTIPLY_ON)
#define FacetParticleApplyFog(fogCoord, color) UNITY_APPLY_FOG_COLOR(fogCoord, color, (_DstBlend == 1 ? fixed4(0, 0, 0, 0) : unity_FogColor))
#else
#define FacetParticleApplyFog(fogCoord, color) UNITY_APPLY_FOG(fogCoord, color)
#endif

void vertParticleUnlit(appdata_particles v, out VertexOutput o)
{
    UNITY_SETUP_INSTANCE_ID(v);
    UNITY_INITIALIZE_OUTPUT(VertexOutput, o);
    UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO(o);
    float4 clipPosition = UnityObjectToClipPos(v.vertex);
    FacetParticleVertexShared(v, o);
    o.vertex = clipPosition;
    o.color = v.color;
    UNITY_TRANSFER_FOG(o, clipPosition);
}

half4 fragParticleUnlit(VertexOutput input) : SV_Target
{
    half4 albedo = readTexture(_MainTex, input) * _Color;
    fragColorMode(input);
    fragSoftParticles(input);
    fragCameraFading(input);
    float3 normal = FacetParticleNormal(input);
    fragDistortion(input);

    half4 result = albedo;
#if defined(_ALPHAMODULATE_ON)
    result.rgb = FacetParticleModulate(albedo);
#endif
#if defined(_EMISSION)
    result.rgb += readTexture(_EmissionMap, input).rgb * _EmissionColor * cameraFade * softParticlesFade;
#endif
    result.a = FacetParticleOutputAlpha(result.a);
    FacetParticleAlphaTest(albedo.a);
    FacetParticleApplyFog(input.fogCoord, result);
    return result;
}

#endif // UNITY_STANDARD_PARTICLES_INCLUDED
