// The Standard particle shaders' editor passes (scene selection outline and
// picking): vertEditorPass, fragSceneHighlightPass (writes _ObjectId,
// _PassValue) and fragScenePickingPass (writes _SelectionID), cut out by the
// particle's alpha under _ALPHATEST_ON. facet draws no editor passes; they
// compile so the shaders do.
#ifndef UNITY_STANDARD_PARTICLE_EDITOR_INCLUDED
#define UNITY_STANDARD_PARTICLE_EDITOR_INCLUDED

#ifdef _REQUIRE_UV2
#define _FLIPBOOK_BLENDING 1
#endif

#include "UnityCG.cginc"
#include "UnityShaderVariables.cginc"
#include "UnityStandardConfig.cginc"
#include "UnityStandardUtils.cginc"
#include "UnityStandardParticleInstancing.cginc"
#include "FacetParticles.hlsl"

// What the editor writes: the object id and pass value for the outline, the
// selection id for picking (with its own alpha cut-off).
float _ObjectId;
float _PassValue;
float4 _SelectionID;
float _SelectionAlphaCutoff;

// The particle's texture and cut-off.
sampler2D _MainTex;
float4 _MainTex_ST;
#ifdef _ALPHATEST_ON
half _Cutoff;
#endif

// Mesh data (the semantics give the locations; fixed is float).
struct VertexInput
{
    float4 vertex : POSITION;
    float4 color : COLOR;
    float3 normal : NORMAL;
#ifndef _FLIPBOOK_BLENDING
    float2 texcoords : TEXCOORD0;
#else
    float4 texcoords : TEXCOORD0;   // this frame in xy, the next one in zw
    float texcoordBlend : TEXCOORD1;
#endif
    UNITY_VERTEX_INPUT_INSTANCE_ID
};

struct VertexOutput
{
    float4 color : TEXCOORD2;
    float2 texcoord : TEXCOORD0;
#ifdef _FLIPBOOK_BLENDING
    float3 texcoord2AndBlend : TEXCOORD1;
#endif
};

// The particle's alpha: texture (both flipbook frames where on) times vertex.
half FacetParticleEditorAlpha(VertexOutput i)
{
#ifndef _FLIPBOOK_BLENDING
    half4 texel = tex2D(_MainTex, i.texcoord);
#else
    half4 texel = FacetFlipbookSample(_MainTex, i.texcoord, i.texcoord2AndBlend.xy, i.texcoord2AndBlend.z);
#endif
    return texel.a * i.color.a;
}

void vertEditorPass(VertexInput v, out VertexOutput o, out float4 opos : SV_POSITION)
{
    UNITY_SETUP_INSTANCE_ID(v);
    o.color = v.color;
#ifndef _FLIPBOOK_BLENDING
    o.texcoord = TRANSFORM_TEX(v.texcoords.xy, _MainTex);
#else
    o.texcoord = v.texcoords.xy;
    o.texcoord2AndBlend = float3(v.texcoords.zw, v.texcoordBlend);
#endif
    opos = UnityObjectToClipPos(v.vertex);
}

// Cut-out particles are outlined and picked only where they are drawn.
void fragSceneClip(VertexOutput i)
{
#ifdef _ALPHATEST_ON
    clip(FacetParticleEditorAlpha(i) - _Cutoff);
#endif
}

// Outline: the object id and pass value; picking: the selection id.
half4 fragSceneHighlightPass(VertexOutput i) : SV_Target { fragSceneClip(i); return float4(_ObjectId, _PassValue, 1, 1); }
half4 fragScenePickingPass(VertexOutput i) : SV_Target { fragSceneClip(i); return _SelectionID; }

#endif // UNITY_STANDARD_PARTICLE_EDITOR_INCLUDED
