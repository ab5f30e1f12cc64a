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
// _NORMALMAP; either one turns the layer normal maps on.
#if defined(_NORMALMAP) && !defined(_TERRAIN_NORMAL_MAP)
    #define _TERRAIN_NORMAL_MAP
#elif !defined(_NORMALMAP) && defined(_TERRAIN_NORMAL_MAP)
    #define _NORMALMAP
#endif

struct Input
{
    float4 tc;   // xy: terrain uv (0..1 over the tile); zw: heightmap uv (instanced per-pixel normals)
#ifndef TERRAIN_BASE_PASS
    UNITY_FOG_COORDS(0)   // finalcolor applies the fog itself (black in add passes)
#endif
};

// Material values: loose globals ("$Globals" / material set, filled by name;
// _Control_TexelSize and the _ST values by the runtime's texel-size and
// scale-offset roles).
sampler2D _Control;
float4 _Control_ST;
float4 _Control_TexelSize;
sampler2D _Splat0, _Splat1, _Splat2, _Splat3;
float4 _Splat0_ST, _Splat1_ST, _Splat2_ST, _Splat3_ST;

#if defined(UNITY_INSTANCING_ENABLED)
    // Instanced terrain: every patch is the same grid mesh, displaced by the
    // heightmap in the vertex stage.
    sampler2D _TerrainHeightmapTexture;
    sampler2D _TerrainNormalmapTexture;
    float4 _TerrainHeightmapRecipSize;   // (1/width, 1/height, 1/(width-1), 1/(height-1))
    float4 _TerrainHeightmapScale;       // (size.x, size.y / max height, size.z, 0)
#endif

UNITY_INSTANCING_BUFFER_START(Terrain)
    UNITY_DEFINE_INSTANCED_PROP(float4, _TerrainPatchInstanceData)  // (x base, z base, skip scale, -)
UNITY_INSTANCING_BUFFER_END(Terrain)

#ifdef _NORMALMAP
    sampler2D _Normal0, _Normal1, _Normal2, _Normal3;
    float _NormalScale0, _NormalScale1, _NormalScale2, _NormalScale3;
#endif

#ifdef _ALPHATEST_ON
    sampler2D _TerrainHolesTexture;

    // Terrain holes: texels below a small epsilon (compressed maps do not
    // store an exact 0) are cut out.
    void ClipHoles(float2 uv)
    {
        float hole = tex2D(_TerrainHolesTexture, uv).r;
        clip(hole < 0.0005f ? -1 : 1);
    }
#endif

#if defined(TERRAIN_BASE_PASS) && defined(UNITY_PASS_META)
    float4 _MainTex_ST;   // the base map's tiling, for lightmap baking
#endif

// Heightmaps are 16-bit single-channel textures on every facet target.
inline float FacetTerrainUnpackHeight(float4 texel)
{
    return texel.r;
}

void SplatmapVert(inout appdata_full v, out Input data)
{
    UNITY_INITIALIZE_OUTPUT(Input, data);

#if defined(UNITY_INSTANCING_ENABLED)
    // The patch's grid vertex (x, z in vertex.xy) placed by the instance's
    // base and level of detail (skip scale), lifted by the heightmap.
    float2 patchVertex = v.vertex.xy;
    float4 instanceData = UNITY_ACCESS_INSTANCED_PROP(Terrain, _TerrainPatchInstanceData);
    float4 uvScale = instanceData.z * _TerrainHeightmapRecipSize;
    float4 uvOffset = instanceData.xyxy * uvScale;
    uvOffset.xy += 0.5f * _TerrainHeightmapRecipSize.xy;   // texel centres
    float2 sampleCoords = patchVertex * uvScale.xy + uvOffset.xy;

    float height = FacetTerrainUnpackHeight(tex2Dlod(_TerrainHeightmapTexture, float4(sampleCoords, 0, 0)));
    v.vertex.xz = (patchVertex + instanceData.xy) * _TerrainHeightmapScale.xz * instanceData.z;
    v.vertex.y = height * _TerrainHeightmapScale.y;
    v.vertex.w = 1.0f;

    v.texcoord.xy = patchVertex * uvScale.zw + uvOffset.zw;
    v.texcoord3 = v.texcoord2 = v.texcoord1 = v.texcoord;

    #ifdef TERRAIN_INSTANCED_PERPIXEL_NORMAL
        v.normal = float3(0, 1, 0);   // the fragment stage reads the normal map
        data.tc.zw = sampleCoords;
    #else
        v.normal = tex2Dlod(_TerrainNormalmapTexture, float4(sampleCoords, 0, 0)).xyz * 2.0f - 1.0f;
    #endif
#endif

    // The terrain mesh has no tangents: a tangent frame with u along +x
    // (cross of the normal with +z), so layer normal maps have a basis.
    v.tangent.xyz = cross(v.normal, float3(0, 0, 1));
    v.tangent.w = -1;

    data.tc.xy = v.texcoord.xy;
#ifdef TERRAIN_BASE_PASS
    #ifdef UNITY_PASS_META
        data.tc.xy = TRANSFORM_TEX(v.texcoord.xy, _MainTex);
    #endif
#else
    float4 clipPos = UnityObjectToClipPos(v.vertex);
    UNITY_TRANSFER_FOG(data, clipPos);
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

    // Put the terrain's edges on the control map's texel centres. Without a
    // texel size (a shader with no _Control property, nothing filled it) the
    // uv is used as it is.
    float2 controlUV = data.tc.xy;
    if (_Control_TexelSize.z > 0.0)
        controlUV = (data.tc.xy * (_Control_TexelSize.zw - 1.0f) + 0.5f) * _Control_TexelSize.xy;
    splat_control = tex2D(_Control, controlUV);
    weight = dot(splat_control, half4(1, 1, 1, 1));

#if !defined(SHADER_API_MOBILE) && defined(TERRAIN_SPLAT_ADDPASS)
    clip(weight == 0.0f ? -1 : 1);   // nothing of this group here: leave the pixel alone
#endif

    splat_control /= (weight + 1e-3f);

    float2 uv0 = TRANSFORM_TEX(data.tc.xy, _Splat0);
    float2 uv1 = TRANSFORM_TEX(data.tc.xy, _Splat1);
    float2 uv2 = TRANSFORM_TEX(data.tc.xy, _Splat2);
    float2 uv3 = TRANSFORM_TEX(data.tc.xy, _Splat3);

#ifdef TERRAIN_STANDARD_SHADER
    const half4 layerAlpha = defaultAlpha;   // rgb from the layer, alpha (smoothness) scaled per layer
#else
    const half4 layerAlpha = half4(1, 1, 1, 1);
#endif
    mixedDiffuse = splat_control.r * tex2D(_Splat0, uv0) * half4(1, 1, 1, layerAlpha.r)
                 + splat_control.g * tex2D(_Splat1, uv1) * half4(1, 1, 1, layerAlpha.g)
                 + splat_control.b * tex2D(_Splat2, uv2) * half4(1, 1, 1, layerAlpha.b)
                 + splat_control.a * tex2D(_Splat3, uv3) * half4(1, 1, 1, layerAlpha.a);

#ifdef _NORMALMAP
    mixedNormal = FacetUnpackScaleNormal(tex2D(_Normal0, uv0), _NormalScale0) * splat_control.r
                + FacetUnpackScaleNormal(tex2D(_Normal1, uv1), _NormalScale1) * splat_control.g
                + FacetUnpackScaleNormal(tex2D(_Normal2, uv2), _NormalScale2) * splat_control.b
                + FacetUnpackScaleNormal(tex2D(_Normal3, uv3), _NormalScale3) * splat_control.a;
    mixedNormal.z += 1e-5f;   // never exactly zero, so normalising later gives no NaN
#endif

#if defined(UNITY_INSTANCING_ENABLED) && defined(TERRAIN_INSTANCED_PERPIXEL_NORMAL)
    // Per-pixel normal from the terrain's normal map (world y-up); the layer
    // normal is rotated into its frame. The result is swizzled to xzy, the
    // tangent-space order of the vertex frame (tangent x, bitangent z, normal y).
    float3 geomNormal = normalize(tex2D(_TerrainNormalmapTexture, data.tc.zw).xyz * 2 - 1);
    #ifdef _NORMALMAP
        float3 geomTangent = normalize(cross(geomNormal, float3(0, 0, 1)));
        float3 geomBitangent = normalize(cross(geomTangent, geomNormal));
        mixedNormal = mixedNormal.x * geomTangent + mixedNormal.y * geomBitangent + mixedNormal.z * geomNormal;
    #else
        mixedNormal = geomNormal;
    #endif
    mixedNormal = mixedNormal.xzy;
#endif
}

#ifndef TERRAIN_SURFACE_OUTPUT
    #define TERRAIN_SURFACE_OUTPUT SurfaceOutput
#endif

// finalcolor: restore the weight taken out by SplatmapMix, then fog (towards
// black in add passes, so the fog colour is added only once).
void SplatmapFinalColor(Input data, TERRAIN_SURFACE_OUTPUT o, inout fixed4 color)
{
    color *= o.Alpha;
#ifdef TERRAIN_SPLAT_ADDPASS
    UNITY_APPLY_FOG_COLOR(data.fogCoord, color, fixed4(0, 0, 0, 0));
#else
    UNITY_APPLY_FOG(data.fogCoord, color);
#endif
}

// finalprepass (legacy deferred lighting): weight the normal/specular buffer.
void SplatmapFinalPrepass(Input data, TERRAIN_SURFACE_OUTPUT o, inout fixed4 normalSpec)
{
    normalSpec *= o.Alpha;
}

// finalgbuffer (deferred): weight diffuse, specular/smoothness, normal and
// emission. (What UnityGBuffer.cginc's UnityStandardDataApplyWeightToGbuffer
// does; written out so this file does not depend on the deferred library.)
void SplatmapFinalGBuffer(Input data, TERRAIN_SURFACE_OUTPUT o, inout half4 outGBuffer0, inout half4 outGBuffer1, inout half4 outGBuffer2, inout half4 emission)
{
    outGBuffer0.rgb *= o.Alpha;
    outGBuffer1 *= o.Alpha;
    outGBuffer2.xyz *= o.Alpha;
    emission *= o.Alpha;
}

#endif // TERRAIN_BASE_PASS

#endif // TERRAIN_SPLATMAP_COMMON_CGINC_INCLUDED
