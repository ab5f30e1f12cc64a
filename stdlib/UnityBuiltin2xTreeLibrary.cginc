// facet's soft-occlusion tree library (Unity 2.x-style trees): the vertex
// programs `leaves` and `bark` and their v2f, under Unity's names, used by
// the TreeSoftOcclusion* shaders. Lighting is per vertex: ambient plus up to
// four lights, each weighted by the tree's baked directional occlusion.
#ifndef UNITY_BUILTIN_2X_TREE_LIBRARY_INCLUDED
#define UNITY_BUILTIN_2X_TREE_LIBRARY_INCLUDED

#include "HLSLSupport.cginc"
#include "UnityCG.cginc"
#include "TerrainEngine.cginc"

// Material values (loose globals: "$Globals", filled by name).
float _Occlusion, _AO, _BaseLight;
fixed4 _Color;
float _HalfOverCutoff;   // 0.5 / cutoff: leaves output alpha 0.5 * this

#ifdef USE_CUSTOM_LIGHT_DIR
// Rendering a tree into its billboard texture: four fixed lights given in
// world space by the terrain engine (loose globals, filled by name).
float3 _TerrainTreeLightDirections[4];
float4 _TerrainTreeLightColors[4];
#endif

// unity_LightPosition, unity_LightColor and unity_LightAtten (Unity's
// legacy per-vertex lights, view space) are facet built-ins
// (FacetBuiltins.hlsl, cbuffer FacetPerLightUnity).

struct v2f {
    float4 pos : SV_POSITION;
    float4 uv : TEXCOORD0;
    half4 color : TEXCOORD1;
    UNITY_FOG_COORDS(2)
    UNITY_VERTEX_OUTPUT_STEREO
};

// Light i as a world-space unit direction and a colour already multiplied by
// its attenuation.
void FacetTreeLight(int i, float3 viewPos, out float3 dir, out float4 color)
{
#ifdef USE_CUSTOM_LIGHT_DIR
    dir = _TerrainTreeLightDirections[i];
    color = _TerrainTreeLightColors[i];
#else
    // view space (right-handed, -Z forward) -> camera space (+Z forward) ->
    // world: unity_CameraToWorld is the +Z-forward camera's frame.
    float3 toLight = unity_LightPosition[i].xyz - viewPos * unity_LightPosition[i].w;
    float atten = 1.0 / (1.0 + dot(toLight, toLight) * unity_LightAtten[i].z);
    toLight.z = -toLight.z;
    dir = mul((float3x3)unity_CameraToWorld, normalize(toLight));
    color = float4(unity_LightColor[i].rgb * atten, 0);
#endif
}

// Leaves: tangent holds the baked directional occlusion (xyz) and ambient
// occlusion (w); each light adds colour * (max(0, occlusion . L) + base).
v2f leaves(appdata_tree v)
{
    v2f o;
    UNITY_SETUP_INSTANCE_ID(v);
    UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO(o);
    TerrainAnimateTree(v.vertex, v.color.w);

    float3 viewPos = UnityObjectToViewPos(v.vertex);
    o.pos = UnityObjectToClipPos(v.vertex);
    o.uv = v.texcoord;

    float4 light = UNITY_LIGHTMODEL_AMBIENT;
    for (int i = 0; i < 4; i++) {
        float3 dir; float4 color;
        FacetTreeLight(i, viewPos, dir, color);
        float occ = max(0, dot(v.tangent, float4(dir * _Occlusion, _AO))) + _BaseLight;
        light += color * occ;
    }

    o.color = light * _Color * _TreeInstanceColor;
    o.color.a = 0.5 * _HalfOverCutoff;
    UNITY_TRANSFER_FOG(o, o.pos);
    return o;
}

// Bark: plain N.L per light, scaled by the ambient occlusion in tangent.w.
v2f bark(appdata_tree v)
{
    v2f o;
    UNITY_SETUP_INSTANCE_ID(v);
    UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO(o);
    TerrainAnimateTree(v.vertex, v.color.w);

    float3 viewPos = UnityObjectToViewPos(v.vertex);
    o.pos = UnityObjectToClipPos(v.vertex);
    o.uv = v.texcoord;

    float4 light = UNITY_LIGHTMODEL_AMBIENT;
    for (int i = 0; i < 4; i++) {
        float3 dir; float4 color;
        FacetTreeLight(i, viewPos, dir, color);
        float diffuse = max(0, dot(v.normal, dir)) * (_AO * v.tangent.w + _BaseLight);
        light += color * diffuse;
    }

    light.a = 1;
    o.color = light * _Color * _TreeInstanceColor;
#ifdef WRITE_ALPHA_1
    o.color.a = 1;
#endif
    UNITY_TRANSFER_FOG(o, o.pos);
    return o;
}

#endif // UNITY_BUILTIN_2X_TREE_LIBRARY_INCLUDED
