// The Standard shader's forward passes: the per-pixel surface data
// (FragmentCommonData) from the material inputs through
// UNITY_SETUP_BRDF_INPUT (SpecularSetup, MetallicSetup or RoughnessSetup),
// the lights, GI, and the ForwardBase / ForwardAdd vertex and fragment
// functions that UnityStandardCoreForward.cginc exposes as
// vertBase/fragBase/vertAdd/fragAdd, and the Deferred pass's G-buffer
// writer (vertDeferred/fragDeferred). Lighting goes through UNITY_BRDF_PBS, so
// a shader that defines it before including this file swaps the BRDF.
#ifndef UNITY_STANDARD_CORE_INCLUDED
#define UNITY_STANDARD_CORE_INCLUDED

#include "UnityCG.cginc"
#include "UnityShaderVariables.cginc"
#include "UnityStandardConfig.cginc"
#include "UnityStandardInput.cginc"
#include "UnityPBSLighting.cginc"
#include "UnityStandardUtils.cginc"
#include "UnityGlobalIllumination.cginc"
#include "UnityStandardBRDF.cginc"
#include "AutoLight.cginc"
#include "UnityGBuffer.cginc"

// ---- surface data ---------------------------------------------------------------
struct FragmentCommonData
{
    half3 diffColor, specColor;
    // 1 - reflectivity: the diffuse share of the light, used for premultiplied
    // alpha and the grazing reflection term.
    half oneMinusReflectivity, smoothness;
    float3 normalWorld;
    float3 eyeVec;   // from the eye to the surface, unit length
    half alpha;
    float3 posWorld;
};

inline FragmentCommonData SpecularSetup(float4 i_tex)
{
    half4 specGloss = SpecularGloss(i_tex.xy);
    half oneMinusReflectivity;
    half3 diffColor = EnergyConservationBetweenDiffuseAndSpecular(Albedo(i_tex), specGloss.rgb, oneMinusReflectivity);
    FragmentCommonData o = (FragmentCommonData)0;
    o.diffColor = diffColor;
    o.specColor = specGloss.rgb;
    o.oneMinusReflectivity = oneMinusReflectivity;
    o.smoothness = specGloss.a;
    return o;
}

inline FragmentCommonData MetallicSetup(float4 i_tex)
{
    half2 metallicGloss = MetallicGloss(i_tex.xy);
    half3 specColor;
    half oneMinusReflectivity;
    half3 diffColor = DiffuseAndSpecularFromMetallic(Albedo(i_tex), metallicGloss.x, specColor, oneMinusReflectivity);
    FragmentCommonData o = (FragmentCommonData)0;
    o.diffColor = diffColor;
    o.specColor = specColor;
    o.oneMinusReflectivity = oneMinusReflectivity;
    o.smoothness = metallicGloss.y;
    return o;
}

inline FragmentCommonData RoughnessSetup(float4 i_tex)
{
    half2 metallicGloss = MetallicRough(i_tex.xy);
    half3 specColor;
    half oneMinusReflectivity;
    half3 diffColor = DiffuseAndSpecularFromMetallic(Albedo(i_tex), metallicGloss.x, specColor, oneMinusReflectivity);
    FragmentCommonData o = (FragmentCommonData)0;
    o.diffColor = diffColor;
    o.specColor = specColor;
    o.oneMinusReflectivity = oneMinusReflectivity;
    o.smoothness = metallicGloss.y;
    return o;
}

// The specular setup unless the shader picks another (Standard.shader
// defines MetallicSetup in its CGINCLUDE).
#ifndef UNITY_SETUP_BRDF_INPUT
#define UNITY_SETUP_BRDF_INPUT SpecularSetup
#endif

half3 NormalizePerVertexNormal(float3 n) { return normalize(n); }
float3 NormalizePerPixelNormal(float3 n) { return normalize(n); }

// tangentToWorld rows: tangent, binormal, normal (xyz; w carries other data).
float3 PerPixelWorldNormal(float4 i_tex, float4 tangentToWorld[3])
{
#ifdef _NORMALMAP
    half3 tangent = tangentToWorld[0].xyz;
    half3 binormal = tangentToWorld[1].xyz;
    half3 normal = tangentToWorld[2].xyz;
    half3 normalTangent = NormalInTangentSpace(i_tex);
    return NormalizePerPixelNormal(tangent * normalTangent.x + binormal * normalTangent.y + normal * normalTangent.z);
#else
    return normalize(tangentToWorld[2].xyz);
#endif
}

// The view direction in tangent space for parallax, packed in the w of the
// three tangentToWorld rows.
#ifdef _PARALLAXMAP
#define IN_VIEWDIR4PARALLAX(i) NormalizePerPixelNormal(float3(i.tangentToWorld0.w, i.tangentToWorld1.w, i.tangentToWorld2.w))
#else
#define IN_VIEWDIR4PARALLAX(i) half3(0, 0, 0)
#endif
#define IN_WORLDPOS(i) i.posWorld

inline FragmentCommonData FragmentSetup(inout float4 i_tex, float3 i_eyeVec, half3 i_viewDirForParallax,
                                        float4 tangentToWorld[3], float3 i_posWorld)
{
    i_tex = Parallax(i_tex, i_viewDirForParallax);
    half alpha = Alpha(i_tex.xy);
#if defined(_ALPHATEST_ON)
    clip(alpha - _Cutoff);
#endif
    FragmentCommonData o = UNITY_SETUP_BRDF_INPUT(i_tex);
    o.normalWorld = PerPixelWorldNormal(i_tex, tangentToWorld);
    o.eyeVec = NormalizePerPixelNormal(i_eyeVec);
    o.posWorld = i_posWorld;
    // Premultiplied transparency: only the diffuse part fades.
    o.diffColor = PreMultiplyAlpha(o.diffColor, alpha, o.oneMinusReflectivity, o.alpha);
    return o;
}

// The three tangentToWorld rows travel as three interpolators (an array
// would share one semantic) and are gathered back into an array here.
#define FRAGMENT_SETUP(x) float4 x##TangentToWorld[3] = { i.tangentToWorld0, i.tangentToWorld1, i.tangentToWorld2 }; \
    FragmentCommonData x = FragmentSetup(i.tex, i.eyeVec.xyz, IN_VIEWDIR4PARALLAX(i), x##TangentToWorld, IN_WORLDPOS(i));
#define FRAGMENT_SETUP_FWDADD(x) FRAGMENT_SETUP(x)

// ---- lights and GI -------------------------------------------------------------------
// The pass's light: the main directional light in ForwardBase.
UnityLight MainLight()
{
    UnityLight l;
    l.color = _LightColor0.rgb;
    l.dir = _WorldSpaceLightPos0.xyz;
    l.ndotl = 0;
    return l;
}

// The ForwardAdd light towards a surface point, attenuated.
UnityLight AdditiveLight(half3 lightDir, half atten)
{
    UnityLight l;
    l.color = _LightColor0.rgb * atten;
    l.dir = NormalizePerPixelNormal(lightDir);
    l.ndotl = 0;
    return l;
}

UnityLight DummyLight()
{
    UnityLight l;
    l.color = 0;
    l.dir = half3(0, 1, 0);
    l.ndotl = 0;
    return l;
}

UnityIndirect ZeroIndirect()
{
    UnityIndirect ind;
    ind.diffuse = 0;
    ind.specular = 0;
    return ind;
}

inline UnityGI FragmentGI(FragmentCommonData s, half occlusion, half4 i_ambientOrLightmapUV, half atten,
                          UnityLight light, bool reflections)
{
    UnityGIInput d = (UnityGIInput)0;
    d.light = light;
    d.worldPos = s.posWorld;
    d.worldViewDir = -s.eyeVec;
    d.atten = atten;
    d.ambient = i_ambientOrLightmapUV.rgb;
    d.lightmapUV = 0;
    FacetSetupGIInputProbes(d);
    if (reflections) {
        Unity_GlossyEnvironmentData g = UnityGlossyEnvironmentSetup(s.smoothness, -s.eyeVec, s.normalWorld, s.specColor);
        return UnityGlobalIllumination(d, occlusion, s.normalWorld, g);
    }
    return UnityGlobalIllumination(d, occlusion, s.normalWorld);
}

inline UnityGI FragmentGI(FragmentCommonData s, half occlusion, half4 i_ambientOrLightmapUV, half atten, UnityLight light)
{
    return FragmentGI(s, occlusion, i_ambientOrLightmapUV, atten, light, true);
}

// Opaque and cutout variants write alpha 1; Fade/Transparent keep the
// surface's alpha.
#if defined(_ALPHABLEND_ON) || defined(_ALPHAPREMULTIPLY_ON)
half4 OutputForward(half4 output, half alphaFromSurface) { return half4(output.rgb, alphaFromSurface); }
#else
half4 OutputForward(half4 output, half alphaFromSurface) { UNITY_OPAQUE_ALPHA(output.a); return output; }
#endif

// Per-vertex ambient: ForwardBase's four per-vertex point lights
// (VERTEXLIGHT_ON) and what ShadeSHPerVertex adds to them; facet evaluates
// the SH itself per pixel (ShadeSHPerPixel).
inline half4 VertexGIForward(VertexInput v, float3 posWorld, half3 normalWorld)
{
    half3 vertexLights = 0;
#ifdef VERTEXLIGHT_ON
    vertexLights = Shade4PointLights(unity_4LightPosX0, unity_4LightPosY0, unity_4LightPosZ0,
                                     unity_LightColor[0].rgb, unity_LightColor[1].rgb, unity_LightColor[2].rgb,
                                     unity_LightColor[3].rgb, unity_4LightAtten0, posWorld, normalWorld);
#endif
    return half4(ShadeSHPerVertex(normalWorld, vertexLights), 0);
}

// Fills the tangentToWorld rows (and the parallax view direction in w).
void FacetStandardTangentFrame(VertexInput v, half3 normalWorld, out float4 rows[3])
{
#ifdef _TANGENT_TO_WORLD
    float4 tangentWorld = float4(UnityObjectToWorldDir(v.tangent.xyz), v.tangent.w);
    float3x3 tangentToWorld = CreateTangentToWorldPerVertex(normalWorld, tangentWorld.xyz, tangentWorld.w);
    rows[0] = float4(tangentToWorld[0], 0);
    rows[1] = float4(tangentToWorld[1], 0);
    rows[2] = float4(tangentToWorld[2], 0);
#else
    rows[0] = 0;
    rows[1] = 0;
    rows[2] = float4(normalWorld, 0);
#endif
#ifdef _PARALLAXMAP
    float3 binormal = cross(normalize(v.normal), normalize(v.tangent.xyz)) * v.tangent.w;
    float3x3 rotation = float3x3(v.tangent.xyz, binormal, v.normal);
    half3 viewDirForParallax = mul(rotation, ObjSpaceViewDir(v.vertex));
    rows[0].w = viewDirForParallax.x;
    rows[1].w = viewDirForParallax.y;
    rows[2].w = viewDirForParallax.z;
#endif
}

// ---- ForwardBase ----------------------------------------------------------------------
struct VertexOutputForwardBase
{
    UNITY_POSITION(pos);
    float4 tex : TEXCOORD0;
    float4 eyeVec : TEXCOORD1;                       // xyz: eye -> vertex
    float4 tangentToWorld0 : TEXCOORD2;  // rows of tangentToWorld | viewDirForParallax in w
    float4 tangentToWorld1 : TEXCOORD3;
    float4 tangentToWorld2 : TEXCOORD4;
    half4 ambientOrLightmapUV : TEXCOORD5;
    UNITY_SHADOW_COORDS(6)
    UNITY_FOG_COORDS(7)
    float3 posWorld : TEXCOORD8;
    UNITY_VERTEX_INPUT_INSTANCE_ID
    UNITY_VERTEX_OUTPUT_STEREO
};

VertexOutputForwardBase vertForwardBase(VertexInput v)
{
    UNITY_SETUP_INSTANCE_ID(v);
    VertexOutputForwardBase o;
    UNITY_INITIALIZE_OUTPUT(VertexOutputForwardBase, o);
    UNITY_TRANSFER_INSTANCE_ID(v, o);
    UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO(o);

    float4 posWorld = mul(unity_ObjectToWorld, v.vertex);
    o.posWorld = posWorld.xyz;
    o.pos = UnityObjectToClipPos(v.vertex);
    o.tex = TexCoords(v);
    o.eyeVec = float4(NormalizePerVertexNormal(posWorld.xyz - _WorldSpaceCameraPos), 0);
    float3 normalWorld = UnityObjectToWorldNormal(v.normal);
    float4 rows[3];
    FacetStandardTangentFrame(v, normalWorld, rows);
    o.tangentToWorld0 = rows[0];
    o.tangentToWorld1 = rows[1];
    o.tangentToWorld2 = rows[2];
    UNITY_TRANSFER_SHADOW(o, v.uv1);
    o.ambientOrLightmapUV = VertexGIForward(v, posWorld.xyz, normalWorld);
    UNITY_TRANSFER_FOG(o, o.pos);
    return o;
}

half4 fragForwardBaseInternal(VertexOutputForwardBase i)
{
    FRAGMENT_SETUP(s)
    UNITY_SETUP_INSTANCE_ID(i);
    UNITY_SETUP_STEREO_EYE_INDEX_POST_VERTEX(i);

    UnityLight mainLight = MainLight();
    UNITY_LIGHT_ATTENUATION(atten, i, s.posWorld);

    half occlusion = Occlusion(i.tex.xy);
    UnityGI gi = FragmentGI(s, occlusion, i.ambientOrLightmapUV, atten, mainLight);

    half4 c = UNITY_BRDF_PBS(s.diffColor, s.specColor, s.oneMinusReflectivity, s.smoothness, s.normalWorld, -s.eyeVec,
                             gi.light, gi.indirect);
    c.rgb += Emission(i.tex.xy);
    UNITY_APPLY_FOG(i.fogCoord, c);
    return OutputForward(c, s.alpha);
}

half4 fragForwardBase(VertexOutputForwardBase i) : SV_Target { return fragForwardBaseInternal(i); }

// ---- ForwardAdd ------------------------------------------------------------------------
struct VertexOutputForwardAdd
{
    UNITY_POSITION(pos);
    float4 tex : TEXCOORD0;
    float4 eyeVec : TEXCOORD1;
    float4 tangentToWorld0 : TEXCOORD2;
    float4 tangentToWorld1 : TEXCOORD3;
    float4 tangentToWorld2 : TEXCOORD4;
    float3 posWorld : TEXCOORD5;
    UNITY_SHADOW_COORDS(6)
    UNITY_FOG_COORDS(7)
    UNITY_VERTEX_OUTPUT_STEREO
};

VertexOutputForwardAdd vertForwardAdd(VertexInput v)
{
    UNITY_SETUP_INSTANCE_ID(v);
    VertexOutputForwardAdd o;
    UNITY_INITIALIZE_OUTPUT(VertexOutputForwardAdd, o);
    UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO(o);

    float4 posWorld = mul(unity_ObjectToWorld, v.vertex);
    o.pos = UnityObjectToClipPos(v.vertex);
    o.tex = TexCoords(v);
    o.eyeVec = float4(NormalizePerVertexNormal(posWorld.xyz - _WorldSpaceCameraPos), 0);
    o.posWorld = posWorld.xyz;
    float3 normalWorld = UnityObjectToWorldNormal(v.normal);
    float4 rows[3];
    FacetStandardTangentFrame(v, normalWorld, rows);
    o.tangentToWorld0 = rows[0];
    o.tangentToWorld1 = rows[1];
    o.tangentToWorld2 = rows[2];
    UNITY_TRANSFER_SHADOW(o, v.uv1);
    UNITY_TRANSFER_FOG(o, o.pos);
    return o;
}

half4 fragForwardAddInternal(VertexOutputForwardAdd i)
{
    FRAGMENT_SETUP_FWDADD(s)
    UNITY_SETUP_STEREO_EYE_INDEX_POST_VERTEX(i);

    // Per pixel, so point and spot lights stay correct on large triangles.
    UNITY_LIGHT_ATTENUATION(atten, i, s.posWorld);
    UnityLight light = AdditiveLight(UnityWorldSpaceLightDir(s.posWorld), atten);
    UnityIndirect noIndirect = ZeroIndirect();

    half4 c = UNITY_BRDF_PBS(s.diffColor, s.specColor, s.oneMinusReflectivity, s.smoothness, s.normalWorld, -s.eyeVec,
                             light, noIndirect);
    // Additive: fog fades towards black so it is not added once per light.
    UNITY_APPLY_FOG_COLOR(i.fogCoord, c, half4(0, 0, 0, 0));
    return OutputForward(c, s.alpha);
}

half4 fragForwardAdd(VertexOutputForwardAdd i) : SV_Target { return fragForwardAddInternal(i); }

// ---- Deferred ---------------------------------------------------------------------
// The G-buffer pass: no analytic light, only the surface (UnityGBuffer.cginc's
// layout in targets 0..2) and what the surface gives off by itself, ambient
// and reflections through GI plus emission, in target 3. Without UNITY_HDR_ON
// target 3 is a logarithmically encoded buffer (exp2(-x)), as Unity's LDR
// light buffer expects.
struct VertexOutputDeferred
{
    UNITY_POSITION(pos);
    float4 tex : TEXCOORD0;
    float3 eyeVec : TEXCOORD1;           // eye -> vertex
    float4 tangentToWorld0 : TEXCOORD2;  // rows of tangentToWorld | viewDirForParallax in w
    float4 tangentToWorld1 : TEXCOORD3;
    float4 tangentToWorld2 : TEXCOORD4;
    half4 ambientOrLightmapUV : TEXCOORD5;
    float3 posWorld : TEXCOORD6;
    UNITY_VERTEX_INPUT_INSTANCE_ID
    UNITY_VERTEX_OUTPUT_STEREO
};

VertexOutputDeferred vertDeferred(VertexInput v)
{
    UNITY_SETUP_INSTANCE_ID(v);
    VertexOutputDeferred o;
    UNITY_INITIALIZE_OUTPUT(VertexOutputDeferred, o);
    UNITY_TRANSFER_INSTANCE_ID(v, o);
    UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO(o);

    float4 posWorld = mul(unity_ObjectToWorld, v.vertex);
    o.posWorld = posWorld.xyz;
    o.pos = UnityObjectToClipPos(v.vertex);
    o.tex = TexCoords(v);
    o.eyeVec = NormalizePerVertexNormal(posWorld.xyz - _WorldSpaceCameraPos);
    float3 normalWorld = UnityObjectToWorldNormal(v.normal);
    float4 rows[3];
    FacetStandardTangentFrame(v, normalWorld, rows);
    o.tangentToWorld0 = rows[0];
    o.tangentToWorld1 = rows[1];
    o.tangentToWorld2 = rows[2];
    o.ambientOrLightmapUV = VertexGIForward(v, posWorld.xyz, normalWorld);
    return o;
}

void fragDeferred(VertexOutputDeferred i,
                  out half4 outGBuffer0 : SV_Target0,
                  out half4 outGBuffer1 : SV_Target1,
                  out half4 outGBuffer2 : SV_Target2,
                  out half4 outEmission : SV_Target3
#if defined(SHADOWS_SHADOWMASK) && (UNITY_ALLOWED_MRT_COUNT > 4)
                  , out half4 outShadowMask : SV_Target4
#endif
)
{
    UNITY_APPLY_DITHER_CROSSFADE(i.pos.xy);
    FRAGMENT_SETUP(s)
    UNITY_SETUP_INSTANCE_ID(i);

    // The lights come later, from the G-buffer; here only GI.
    half occlusion = Occlusion(i.tex.xy);
    // With reflection buffers the reflection probes are drawn as their own
    // deferred pass; otherwise the surface samples them here.
#if UNITY_ENABLE_REFLECTION_BUFFERS
    bool reflections = false;
#else
    bool reflections = true;
#endif
    UnityGI gi = FragmentGI(s, occlusion, i.ambientOrLightmapUV, 1.0, DummyLight(), reflections);
    half3 selfLit = UNITY_BRDF_PBS(s.diffColor, s.specColor, s.oneMinusReflectivity, s.smoothness, s.normalWorld,
                                   -s.eyeVec, gi.light, gi.indirect).rgb;
#ifdef _EMISSION
    selfLit += Emission(i.tex.xy);
#endif
#ifndef UNITY_HDR_ON
    selfLit = exp2(-selfLit);
#endif

    UnityStandardData gbuffer;
    gbuffer.diffuseColor = s.diffColor;
    gbuffer.occlusion = occlusion;
    gbuffer.specularColor = s.specColor;
    gbuffer.smoothness = s.smoothness;
    gbuffer.normalWorld = s.normalWorld;
    UnityStandardDataToGbuffer(gbuffer, outGBuffer0, outGBuffer1, outGBuffer2);
    outEmission = half4(selfLit, 1);
#if defined(SHADOWS_SHADOWMASK) && (UNITY_ALLOWED_MRT_COUNT > 4)
    outShadowMask = UnityGetRawBakedOcclusions(i.ambientOrLightmapUV.xy, s.posWorld);
#endif
}

// FragmentGI's older signature, from the surface values one by one.
inline UnityGI FragmentGI(float3 posWorld, half occlusion, half4 i_ambientOrLightmapUV, half atten, half smoothness,
                          half3 normalWorld, half3 eyeVec, UnityLight light, bool reflections)
{
    FragmentCommonData s = (FragmentCommonData)0;
    s.smoothness = smoothness;
    s.normalWorld = normalWorld;
    s.eyeVec = eyeVec;
    s.posWorld = posWorld;
    return FragmentGI(s, occlusion, i_ambientOrLightmapUV, atten, light, reflections);
}
inline UnityGI FragmentGI(float3 posWorld, half occlusion, half4 i_ambientOrLightmapUV, half atten, half smoothness,
                          half3 normalWorld, half3 eyeVec, UnityLight light)
{
    return FragmentGI(posWorld, occlusion, i_ambientOrLightmapUV, atten, smoothness, normalWorld, eyeVec, light, true);
}

#endif // UNITY_STANDARD_CORE_INCLUDED
