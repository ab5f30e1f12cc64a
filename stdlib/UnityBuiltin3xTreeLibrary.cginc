// facet's Tree Creator library (Unity 3.x-style trees): the leaf lighting
// model, per-vertex translucent lighting for the "Fast" leaves, the bark and
// leaf vertex modifiers and the billboard dither fade, under Unity's names.
#ifndef UNITY_BUILTIN_3X_TREE_LIBRARY_INCLUDED
#define UNITY_BUILTIN_3X_TREE_LIBRARY_INCLUDED

#include "UnityCG.cginc"
#include "Lighting.cginc"
#include "TerrainEngine.cginc"

// The leaf lighting model's surface: the usual SurfaceOutput members plus
// how much light passes through the leaf.
struct LeafSurfaceOutput
{
    fixed3 Albedo;
    fixed Alpha;
    fixed3 Normal;
    fixed3 Emission;
    half Specular;
    fixed Gloss;
    fixed Translucency;
};

// Material values (loose globals: "$Globals", filled by name).
fixed4 _Color;
half _ShadowStrength;               // how much a directional light's shadow darkens leaves
fixed3 _TranslucencyColor;
fixed _TranslucencyViewDependency;  // 0: back light follows -N.L, 1: follows -V.L

// How much light comes through the leaf from behind: the back side's N.L,
// blended towards "looking into the light" (-V.L) by the view dependency.
inline half FacetTreeBackLight(half nl, half3 viewDir, half3 lightDir)
{
    return lerp(saturate(-nl), saturate(dot(viewDir, -lightDir)), _TranslucencyViewDependency);
}

// Leaf lighting (legacy form, called per light): wrap-around diffuse
// (N.L * 0.6 + 0.4, leaves are thin), translucency from behind, Blinn-Phong
// specular; directional lights' shadows are weakened by _ShadowStrength.
inline half4 LightingTreeLeaf(LeafSurfaceOutput s, half3 lightDir, half3 viewDir, half atten)
{
    half3 h = normalize(lightDir + viewDir);
    half nl = dot(s.Normal, lightDir);
    half spec = pow(max(0, dot(s.Normal, h)), s.Specular * 128.0) * s.Gloss;

    fixed3 translucency = FacetTreeBackLight(nl, viewDir, lightDir) * s.Translucency * _TranslucencyColor;
    half wrapped = max(0, nl * 0.6 + 0.4);

    fixed4 c;
    c.rgb = (s.Albedo * (translucency * 2 + wrapped)) * _LightColor0.rgb + spec;
#if defined(DIRECTIONAL) || defined(DIRECTIONAL_COOKIE)
    c.rgb *= lerp(1, atten, _ShadowStrength);
#else
    c.rgb *= atten;
#endif
    c.a = s.Alpha;
    return c;
}

// ---- per-vertex lighting for "Tree Creator Leaves Fast" ------------------

// The pass's main light at an object-space vertex: wrap-around diffuse plus
// translucency, in light colour.
fixed3 ShadeTranslucentMainLight(float4 vertex, float3 normal)
{
    float3 viewDir = normalize(WorldSpaceViewDir(vertex));
    float3 lightDir = normalize(WorldSpaceLightDir(vertex));
    float nl = dot(normal, lightDir);
    fixed diffuse = max(0, nl * 0.6 + 0.4);
    return _LightColor0.rgb * (diffuse + FacetTreeBackLight(nl, viewDir, lightDir) * _TranslucencyColor);
}

// Ambient light from both sides of the leaf: SH in front, SH from behind
// tinted by the translucency colour (faded by how much the view looks into
// the main light), halved because the whole sphere is integrated. facet has
// no per-vertex lights, so VERTEXLIGHT_ON adds nothing here.
fixed3 ShadeTranslucentLights(float4 vertex, float3 normal)
{
    float3 viewDir = normalize(WorldSpaceViewDir(vertex));
    float3 mainLightDir = normalize(WorldSpaceLightDir(vertex));
    float3 frontLight = ShadeSH9(float4(normal, 1.0));
    float3 backLight = ShadeSH9(float4(-normal, 1.0));
    fixed backContrib = saturate(dot(viewDir, -mainLightDir));
    backLight = lerp(backLight, backLight * backContrib, _TranslucencyViewDependency);
    return 0.5 * (frontLight + backLight * _TranslucencyColor);
}

// ---- vertex modifiers (surface shaders' vertex:) --------------------------

// Shared tail of the bark and leaf modifiers: instance scale, wind (colour.xy
// = branch phase and edge flutter, uv2 = primary and secondary bend), squash,
// instance colour.
inline void FacetTreeVertCommon(inout appdata_full v)
{
    v.vertex.xyz *= _TreeInstanceScale.xyz;
    v.vertex = AnimateVertex(v.vertex, v.normal, float4(v.color.xy, v.texcoord1.xy));
    v.vertex = Squash(v.vertex);
    v.color.rgb = _TreeInstanceColor.rgb * _Color.rgb;
    v.normal = normalize(v.normal);
    v.tangent.xyz = normalize(v.tangent.xyz);
}

void TreeVertBark(inout appdata_full v)
{
    FacetTreeVertCommon(v);
}

// Leaves first turn their billboard cards to the camera.
void TreeVertLeaf(inout appdata_full v)
{
    ExpandBillboard(UNITY_MATRIX_IT_MV, v.vertex, v.normal, v.tangent);
    FacetTreeVertCommon(v);
}

// ---- dithered fade ----------------------------------------------------------

// Coverage for fading billboards in: c0 = 1 is opaque, below that pixels drop
// out in an 8x8 ordered-dither (Bayer) pattern. The Bayer index is built from
// the pixel's bits (interleaving x^y and y, lowest bit most significant)
// instead of a table; the threshold is (index + 11) / 64. Unity skips this
// below shader model 3.5 on some APIs; on Vulkan it always dithers.
float ScreenDitherToAlpha(float x, float y, float c0)
{
    uint ix = uint(int(x) & 7), iy = uint(int(y) & 7);
    uint index = 0;
    [unroll] for (int bit = 0; bit < 3; ++bit)
    {
        uint xb = (ix >> bit) & 1u, yb = (iy >> bit) & 1u;
        index = (index << 2) | (((xb ^ yb) << 1) | yb);
    }
    float limit = (float(index) + 11.0) / 64.0;
    return lerp(limit * c0, 1.0, c0);
}

// The dither above at a ComputeScreenPos position.
float ComputeAlphaCoverage(float4 screenPos, float fadeAmount)
{
    float2 pixel = screenPos.xy / (screenPos.w + 0.00001) * _ScreenParams.xy;
    return ScreenDitherToAlpha(pixel.x, pixel.y, fadeAmount);
}

#endif // UNITY_BUILTIN_3X_TREE_LIBRARY_INCLUDED
