// facet's terrain splat-map library: the Input struct, vertex function and
// layer mixing that Unity's built-in terrain surface shaders (Nature/Terrain/
// Diffuse, Specular, Standard and their AddPass/Base variants) share.
//
// The control map _Control holds four layer weights (r, g, b, a); each layer
// _SplatN is tiled by its _SplatN_ST. A terrain with more than four layers
// draws the first pass, then AddPass shaders (TERRAIN_SPLAT_ADDPASS) additively
// for each further group of four. Weights are normalised before lighting and
// the lit colour is multiplied by their sum afterwards (SplatmapFinal*), so
// the passes add up to one fully weighted surface.
//
// One file serves the shaders of Unity 2017.4 to Unity 6: the Input struct is
// the later one (uv in tc.xy, shared by all layers through _SplatN_ST);
// 2017's shaders only pass Input on to these functions, so they work with it.
#ifndef TERRAIN_SPLATMAP_COMMON_CGINC_INCLUDED
#define TERRAIN_SPLATMAP_COMMON_CGINC_INCLUDED

#include "UnityCG.cginc"

// Unity 2018.3 renamed the normal-map keyword _TERRAIN_NORMAL_MAP to
// _NORMALMAP; either one turns the layer normal maps on, and both names are
// defined from here on.
#if defined(_TERRAIN_NORMAL_MAP) && !defined(_NORMALMAP)
    #define _NORMALMAP
#endif
#if defined(_NORMALMAP) && !defined(_TERRAIN_NORMAL_MAP)
    #define _TERRAIN_NORMAL_MAP
#endif

// --- Material values ------------------------------------------------------------
// Loose globals ("$Globals" / material set, filled by name; _Control_TexelSize
// and the _ST values by the runtime's texel-size and scale-offset roles).

// The control map: one weight per layer in r, g, b, a.
sampler2D _Control;
float4 _Control_TexelSize;
float4 _Control_ST;

// The four layers: colour (with smoothness in alpha for Standard terrain)
// and, with _NORMALMAP, a normal map with its strength.
sampler2D _Splat0, _Splat1, _Splat2, _Splat3;
float4 _Splat0_ST, _Splat1_ST, _Splat2_ST, _Splat3_ST;
#ifdef _NORMALMAP
    sampler2D _Normal0, _Normal1, _Normal2, _Normal3;
    float _NormalScale0, _NormalScale1, _NormalScale2, _NormalScale3;
#endif

#if defined(TERRAIN_BASE_PASS) && defined(UNITY_PASS_META)
    float4 _MainTex_ST;   // the base map's tiling, for lightmap baking
#endif
#ifdef _ALPHATEST_ON
    sampler2D _TerrainHolesTexture;
#endif

// Instanced terrain: every patch is the same grid mesh, displaced by the
// heightmap in the vertex stage.
UNITY_INSTANCING_BUFFER_START(Terrain)
    UNITY_DEFINE_INSTANCED_PROP(float4, _TerrainPatchInstanceData)  // (x base, z base, skip scale, -)
UNITY_INSTANCING_BUFFER_END(Terrain)
#if defined(UNITY_INSTANCING_ENABLED)
    float4 _TerrainHeightmapScale;       // (size.x, size.y / max height, size.z, 0)
    float4 _TerrainHeightmapRecipSize;   // (1/width, 1/height, 1/(width-1), 1/(height-1))
    sampler2D _TerrainHeightmapTexture;
    sampler2D _TerrainNormalmapTexture;
#endif

// The surface input: xy the terrain uv (0..1 over the tile), zw the
// heightmap uv (instanced per-pixel normals); the fog distance outside the
// base pass, where finalcolor applies the fog itself (black in add passes).
struct Input
{
    float4 tc;
#ifndef TERRAIN_BASE_PASS
    UNITY_FOG_COORDS(0)
#endif
};

// --- facet's terrain helpers ----------------------------------------------------------

// Heightmaps are 16-bit single-channel textures on every facet target.
inline float FacetTerrainUnpackHeight(float4 texel) { return texel.r; }

#ifdef _ALPHATEST_ON
    // Terrain holes: texels below a small epsilon (compressed maps do not
    // store an exact 0) are cut out.
    void ClipHoles(float2 uv)
    {
        bool isHole = tex2D(_TerrainHolesTexture, uv).r < 0.0005f;
        clip(isHole ? -1 : 1);
    }
#endif

#if defined(UNITY_INSTANCING_ENABLED)
// Places the patch's grid vertex (x, z in vertex.xy) by the instance's base
// and level of detail (skip scale), lifts it by the heightmap, and gives it
// the heightmap's normal (or leaves that to the fragment stage).
void FacetTerrainPlaceInstancedVertex(inout appdata_full v, inout Input data)
{
    float2 gridPos = v.vertex.xy;
    float4 patch = UNITY_ACCESS_INSTANCED_PROP(Terrain, _TerrainPatchInstanceData);
    float4 uvScale = patch.z * _TerrainHeightmapRecipSize;
    float4 uvOffset = patch.xyxy * uvScale;
    uvOffset.xy += 0.5f * _TerrainHeightmapRecipSize.xy;   // texel centres
    float2 heightUV = gridPos * uvScale.xy + uvOffset.xy;

    float4 placed;
    placed.xz = (gridPos + patch.xy) * _TerrainHeightmapScale.xz * patch.z;
    placed.y = FacetTerrainUnpackHeight(tex2Dlod(_TerrainHeightmapTexture, float4(heightUV, 0, 0))) * _TerrainHeightmapScale.y;
    placed.w = 1.0f;
    v.vertex = placed;

    v.texcoord.xy = gridPos * uvScale.zw + uvOffset.zw;
    v.texcoord3 = v.texcoord2 = v.texcoord1 = v.texcoord;
#ifdef TERRAIN_INSTANCED_PERPIXEL_NORMAL
    data.tc.zw = heightUV;
    v.normal = float3(0, 1, 0);   // the fragment stage reads the normal map
#else
    v.normal = tex2Dlod(_TerrainNormalmapTexture, float4(heightUV, 0, 0)).xyz * 2.0f - 1.0f;
#endif
}
#endif

// The control-map uv with the terrain's edges on texel centres; without a
// texel size (a shader with no _Control property, nothing filled it) the uv
// as it is.
float2 FacetTerrainControlUV(float2 uv)
{
    if (_Control_TexelSize.z > 0.0)
        uv = (uv * (_Control_TexelSize.zw - 1.0f) + 0.5f) * _Control_TexelSize.xy;
    return uv;
}

// The control weights at uv, normalised, their sum in `total` (an add pass
// leaves pixels where it is 0 alone).
half4 FacetTerrainControlWeights(float2 uv, out half total)
{
    half4 control = tex2D(_Control, FacetTerrainControlUV(uv));
    total = dot(control, half4(1, 1, 1, 1));
#if !defined(SHADER_API_MOBILE) && defined(TERRAIN_SPLAT_ADDPASS)
    clip(total == 0.0f ? -1 : 1);
#endif
    return control / (total + 1e-3f);
}

// What each layer's alpha is scaled by: its smoothness (SplatmapMix's
// defaultAlpha) for Standard terrain, 1 otherwise.
#ifdef TERRAIN_STANDARD_SHADER
#define FacetTerrainAlphaScale defaultAlpha
#else
#define FacetTerrainAlphaScale half4(1, 1, 1, 1)
#endif

// One layer's weighted contribution: its colour, alpha scaled by alphaScale.
half4 FacetTerrainLayerColor(sampler2D tex, float2 uv, half weight, half alphaScale)
{
    return weight * tex2D(tex, uv) * half4(1, 1, 1, alphaScale);
}

#ifdef _NORMALMAP
half3 FacetTerrainLayerNormal(sampler2D tex, float2 uv, float strength, half weight)
{
    return FacetUnpackScaleNormal(tex2D(tex, uv), strength) * weight;
}

// The layers' normals blended by their weights, nudged so that z is never
// exactly zero (normalising it later then gives no NaN).
half3 FacetTerrainMixNormals(float2 layerUV[4], half4 weights)
{
    half3 sum = FacetTerrainLayerNormal(_Normal0, layerUV[0], _NormalScale0, weights.r);
    sum += FacetTerrainLayerNormal(_Normal1, layerUV[1], _NormalScale1, weights.g);
    sum += FacetTerrainLayerNormal(_Normal2, layerUV[2], _NormalScale2, weights.b);
    sum += FacetTerrainLayerNormal(_Normal3, layerUV[3], _NormalScale3, weights.a);
    sum.z += 1e-5f;
    return sum;
}
#endif

#if defined(UNITY_INSTANCING_ENABLED) && defined(TERRAIN_INSTANCED_PERPIXEL_NORMAL)
// The layer normal carried into the frame of the terrain's own normal map
// (world y-up), then swizzled to xzy, the tangent-space order of the vertex
// frame (tangent x, bitangent z, normal y).
fixed3 FacetTerrainPerPixelNormal(float2 heightUV, fixed3 layerNormal)
{
    float3 up = normalize(tex2D(_TerrainNormalmapTexture, heightUV).xyz * 2 - 1);
#ifdef _NORMALMAP
    float3 across = normalize(cross(up, float3(0, 0, 1)));
    float3 along = normalize(cross(across, up));
    float3 world = layerNormal.x * across + layerNormal.y * along + layerNormal.z * up;
#else
    float3 world = up;
#endif
    return world.xzy;
}
#endif

// --- Unity's entry points -----------------------------------------------------------

void SplatmapVert(inout appdata_full v, out Input data)
{
    UNITY_INITIALIZE_OUTPUT(Input, data);
#if defined(UNITY_INSTANCING_ENABLED)
    FacetTerrainPlaceInstancedVertex(v, data);
#endif

    // The terrain mesh has no tangents: a tangent frame with u along +x
    // (cross of the normal with +z), so layer normal maps have a basis.
    v.tangent = float4(cross(v.normal, float3(0, 0, 1)), -1);

#if !defined(TERRAIN_BASE_PASS)
    data.tc.xy = v.texcoord.xy;
    UNITY_TRANSFER_FOG(data, UnityObjectToClipPos(v.vertex));
#elif defined(UNITY_PASS_META)
    data.tc.xy = TRANSFORM_TEX(v.texcoord.xy, _MainTex);
#else
    data.tc.xy = v.texcoord.xy;
#endif
}

#ifndef TERRAIN_BASE_PASS

// Reads the control map, returns its weights normalised (splat_control) and
// their sum (weight, the alpha that SplatmapFinal* multiply by), and the
// weighted mix of the four layers (mixedDiffuse; Standard terrain puts each
// layer's smoothness, defaultAlpha, in the alpha) and of their normal maps
// (mixedNormal, tangent space, only with _NORMALMAP).
#ifdef TERRAIN_STANDARD_SHADER
void SplatmapMix(Input data, half4 defaultAlpha, out half4 splat_control, out half weight, out fixed4 mixedDiffuse, inout fixed3 mixedNormal)
#else
void SplatmapMix(Input data, out half4 splat_control, out half weight, out fixed4 mixedDiffuse, inout fixed3 mixedNormal)
#endif
{
#ifdef _ALPHATEST_ON
    ClipHoles(data.tc.xy);
#endif
    float2 uv = data.tc.xy;
    splat_control = FacetTerrainControlWeights(uv, weight);
    const half4 alphaScale = FacetTerrainAlphaScale;
    float2 layerUV[4] = { TRANSFORM_TEX(uv, _Splat0), TRANSFORM_TEX(uv, _Splat1), TRANSFORM_TEX(uv, _Splat2),
                          TRANSFORM_TEX(uv, _Splat3) };
    mixedDiffuse = FacetTerrainLayerColor(_Splat0, layerUV[0], splat_control.r, alphaScale.r);
    mixedDiffuse += FacetTerrainLayerColor(_Splat1, layerUV[1], splat_control.g, alphaScale.g);
    mixedDiffuse += FacetTerrainLayerColor(_Splat2, layerUV[2], splat_control.b, alphaScale.b);
    mixedDiffuse += FacetTerrainLayerColor(_Splat3, layerUV[3], splat_control.a, alphaScale.a);
#ifdef _NORMALMAP
    mixedNormal = FacetTerrainMixNormals(layerUV, splat_control);
#endif
#if defined(UNITY_INSTANCING_ENABLED) && defined(TERRAIN_INSTANCED_PERPIXEL_NORMAL)
    mixedNormal = FacetTerrainPerPixelNormal(data.tc.zw, mixedNormal);
#endif
}

#ifndef TERRAIN_SURFACE_OUTPUT
    #define TERRAIN_SURFACE_OUTPUT SurfaceOutput
#endif

// The final* functions put back the weight SplatmapMix took out, so that the
// passes add up. finalgbuffer (deferred) weights diffuse, specular/smoothness,
// normal and emission, as UnityGBuffer.cginc's
// UnityStandardDataApplyWeightToGbuffer would (written out here so that this
// file does not need the deferred library).
void SplatmapFinalGBuffer(Input data, TERRAIN_SURFACE_OUTPUT o, inout half4 outGBuffer0, inout half4 outGBuffer1, inout half4 outGBuffer2, inout half4 emission)
{
    half w = o.Alpha;
    outGBuffer0.rgb *= w;
    outGBuffer1 *= w;
    outGBuffer2.xyz *= w;
    emission *= w;
}

// finalprepass (legacy deferred lighting): the normal/specular buffer.
void SplatmapFinalPrepass(Input data, TERRAIN_SURFACE_OUTPUT o, inout fixed4 normalSpec) { normalSpec *= o.Alpha; }

// finalcolor: the colour, then fog (towards black in add passes, so that
// the fog colour is added only once).
void SplatmapFinalColor(Input data, TERRAIN_SURFACE_OUTPUT o, inout fixed4 color)
{
    color *= o.Alpha;
#ifndef TERRAIN_SPLAT_ADDPASS
    UNITY_APPLY_FOG(data.fogCoord, color);
#else
    UNITY_APPLY_FOG_COLOR(data.fogCoord, color, fixed4(0, 0, 0, 0));
#endif
}

#endif // TERRAIN_BASE_PASS

#endif // TERRAIN_SPLATMAP_COMMON_CGINC_INCLUDED
