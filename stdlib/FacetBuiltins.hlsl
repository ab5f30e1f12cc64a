// facet's built-in uniforms: the binding ABI between shaders and the runtime.
// Every declaration has an explicit register(x, spaceN); see
// docs/binding-model.md for the sets and docs/stdlib.md for what each value
// means and who fills it. Member names are Unity's, so Unity code reads them
// directly; the Unity*.cginc files only add macros and functions.
#ifndef FACET_BUILTINS_INCLUDED
#define FACET_BUILTINS_INCLUDED

// ---- set 0: per frame / camera ---------------------------------------------
cbuffer FacetPerFrame : register(b0, space0)
{
    float4x4 unity_MatrixV;             // world -> view (right-handed, looks down -Z)
    float4x4 unity_MatrixInvV;          // view -> world
    float4x4 unity_MatrixP;             // view -> clip (Vulkan clip space, depth 0..1)
    float4x4 unity_MatrixVP;            // world -> clip = P * V
    float4x4 unity_CameraProjection;    // the camera's projection
    float4x4 unity_CameraInvProjection;
    float4x4 unity_WorldToCamera;       // world -> camera (left-handed, looks down +Z)
    float4x4 unity_CameraToWorld;
    float3 _WorldSpaceCameraPos;        // camera position, world space
    float4 _ProjectionParams;           // x = 1 (-1 if flipped), y = near, z = far, w = 1/far
    float4 _ScreenParams;               // x = width, y = height, z = 1 + 1/width, w = 1 + 1/height
    float4 _ZBufferParams;              // x = 1 - far/near, y = far/near, z = x/far, w = y/far
    float4 unity_OrthoParams;           // x = ortho width, y = ortho height, w = 1 orthographic, 0 perspective
    float4 _Time;                       // t/20, t, 2t, 3t (seconds)
    float4 _SinTime;                    // sin(t/8), sin(t/4), sin(t/2), sin(t)
    float4 _CosTime;                    // cos(t/8), cos(t/4), cos(t/2), cos(t)
    float4 unity_DeltaTime;             // dt, 1/dt, smoothed dt, 1/smoothed dt
    float4 unity_FogColor;
    float4 unity_FogParams;             // x = density/sqrt(ln 2), y = density/ln 2, z = -1/(end-start), w = end/(end-start)
    float4 unity_AmbientSky;
    float4 unity_AmbientEquator;
    float4 unity_AmbientGround;
    float4 glstate_lightmodel_ambient;  // flat ambient colour (UNITY_LIGHTMODEL_AMBIENT)
    float4 unity_SHAr;                  // L2 spherical harmonics of the environment's
    float4 unity_SHAg;                  // irradiance, packed as in Sloan's
    float4 unity_SHAb;                  // "Stupid SH tricks" (see ShadeSH9)
    float4 unity_SHBr;
    float4 unity_SHBg;
    float4 unity_SHBb;
    float4 unity_SHC;
    float4 unity_SpecCube0_HDR;         // DecodeHDR instructions of unity_SpecCube0
    float4 unity_SpecCube0_BoxMax;
    float4 unity_SpecCube0_BoxMin;
    float4 unity_SpecCube0_ProbePosition;
};
TextureCube unity_SpecCube0 : register(t1, space0);       // prefiltered environment radiance
SamplerState samplerunity_SpecCube0 : register(s4, space0); // its sampler, which unity_SpecCube1 shares
// _CameraDepthTexture is not declared here: as in Unity, a shader that reads
// the camera's depth declares `sampler2D _CameraDepthTexture;` itself (the
// name is the convention), so it lands in the material set like any texture
// and the runtime binds the depth texture there by name.

// ---- set 1: the light of the pass ------------------------------------------
cbuffer FacetPerLight : register(b0, space1)
{
    float4 _WorldSpaceLightPos0;        // directional: (direction towards the light, 0); else (position, 1)
    float4 _FacetLightColor0;           // colour * intensity; _LightColor0 in UnityLightingCommon.cginc
    float4x4 unity_WorldToLight;        // world -> light space scaled by 1/range (point, spot)
    float4 _LightPositionRange;         // xyz = position, w = 1/range
    float4 _FacetSpotParams;            // x = cos(outer half angle), y = 1/(cos(inner) - cos(outer)), z = 2 tan(outer half angle)
    float4 _LightShadowData;            // x = shadow strength complement (1 - strength)
    float4x4 unity_WorldToShadow[4];
    float4 unity_LightShadowBias;       // ShadowCaster: x = depth bias (clip space), y = 1 to clamp to the near plane, z = normal offset (world units)
    float4 _ShadowMapTexture_TexelSize; // (1/width, 1/height, width, height) of the light's shadow map
    float4 _FacetShadowCascades;        // a directional light's cascades: (count, atlas columns, atlas rows, 0)
};
sampler2D _LightTexture0 : register(s1, space1);          // light cookie: SPOT and DIRECTIONAL_COOKIE multiply by its alpha
// binding 2: sampler2D _ShadowMapTexture, the light's shadow map: declared by
// FacetShadow.hlsl (AutoLight.cginc), so that a program without AutoLight may
// declare its own _ShadowMapTexture as in Unity.

// ---- set 3: per draw (the object) ------------------------------------------
cbuffer FacetPerDraw : register(b0, space3)
{
    float4x4 unity_ObjectToWorld;
    float4x4 unity_WorldToObject;
    float4 unity_LODFade;
    float4 unity_WorldTransformParams;  // w = -1 when the object is mirrored, else 1
};

// ---- Unity built-ins facet does not compute ----------------------------------
// Lightmaps, vertex lights, a second reflection probe, probe volumes, shadow
// cascades: Unity names that shaders read but facet's renderer has no data
// for. They live in blocks of their own, after the ones above, so the
// layouts above stay as they are. The runtime fills blocks by member name
// and leaves unknown members zero, and binds its white fallback texture
// (the environment cube for cubes) to textures it does not know, which is
// what a draw without these features expects: no lightmap scale/offset, no
// vertex lights, unshadowed shadow mask, a second probe with zero HDR decode
// (contributes nothing).
cbuffer FacetPerFrameUnity : register(b2, space0)
{
    float4 unity_CameraWorldClipPlanes[6]; // left, right, bottom, top, near, far (world space)
    float4 unity_ShadowColor;
    float4 unity_SpecCube1_BoxMax;
    float4 unity_SpecCube1_BoxMin;
    float4 unity_SpecCube1_ProbePosition;
    float4 unity_SpecCube1_HDR;
};
TextureCube unity_SpecCube1 : register(t3, space0);       // second (blend) reflection probe, sampled with samplerunity_SpecCube0

cbuffer FacetPerLightUnity : register(b3, space1)
{
    float4 _LightProjectionParams;      // point shadows: x = far/(near-far), y = near*far/(near-far), z = bias, w = scale bias
    float4 unity_4LightPosX0;           // ForwardBase vertex lights: world x of 4 point lights
    float4 unity_4LightPosY0;
    float4 unity_4LightPosZ0;
    float4 unity_4LightAtten0;          // their attenuation factors
    float4 unity_LightColor[8];         // Vertex-lit pass lights: colour
    float4 unity_LightPosition[8];      // view-space (position, 1) or (-direction, 0)
    float4 unity_LightAtten[8];         // x = cos(spot/2), y = 1/cos(spot/4), z = quadratic attenuation, w = range squared
    float4 unity_SpotDirection[8];      // view-space spot direction
    float3 unity_LightColor0;           // old names of the first four vertex-light colours
    float3 unity_LightColor1;
    float3 unity_LightColor2;
    float3 unity_LightColor3;
    float4 unity_OcclusionMaskSelector; // shadow-mask channel of the light
    float4 unity_ShadowSplitSpheres[4]; // cascades
    float4 unity_ShadowSplitSqRadii;
    float4 _LightSplitsNear;
    float4 _LightSplitsFar;
    float4 unity_ShadowFadeCenterAndType;
};

cbuffer FacetPerDrawUnity : register(b1, space3)
{
    float4 unity_LightmapST;            // lightmap uv = uv1 * xy + zw
    float4 unity_DynamicLightmapST;     // realtime lightmap uv = uv2 * xy + zw
    float4 unity_ProbesOcclusion;
    float4 unity_RenderingLayer;
    float4 unity_ProbeVolumeParams;     // x = 1 when the object uses a light probe proxy volume
    float4x4 unity_ProbeVolumeWorldToObject;
    float3 unity_ProbeVolumeSizeInv;
    float3 unity_ProbeVolumeMin;
};
sampler2D unity_Lightmap : register(s2, space3);
sampler2D unity_LightmapInd : register(s3, space3);
sampler2D unity_ShadowMask : register(s4, space3);
sampler2D unity_DynamicLightmap : register(s5, space3);
sampler2D unity_DynamicDirectionality : register(s6, space3);
sampler2D unity_DynamicNormal : register(s7, space3);
sampler3D unity_ProbeVolumeSH : register(s8, space3);
// Unity declares these with UNITY_DECLARE_TEX2D (a texture and a sampler
// sampler<name>); here they are combined samplers, and their sampler names
// name them, which UNITY_SAMPLE_TEX2D's overloads (HLSLSupport.cginc) take.
#define samplerunity_Lightmap unity_Lightmap
#define samplerunity_LightmapInd unity_LightmapInd
#define samplerunity_ShadowMask unity_ShadowMask
#define samplerunity_DynamicLightmap unity_DynamicLightmap
#define samplerunity_DynamicDirectionality unity_DynamicDirectionality
#define samplerunity_DynamicNormal unity_DynamicNormal

#endif // FACET_BUILTINS_INCLUDED
