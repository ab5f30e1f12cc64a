// Cg/HLSL compatibility for glslang's HLSL front end: Cg types, the texture
// macros (facet takes Unity's combined-sampler path: every texture is one
// sampler2D/samplerCUBE descriptor), attributes and platform defines.
// Included implicitly by CGPROGRAM; include it yourself in HLSLPROGRAM.
#ifndef HLSL_SUPPORT_INCLUDED
#define HLSL_SUPPORT_INCLUDED

// Cg's low-precision types are plain float (glslang reads half as float too).
#define fixed float
#define fixed2 float2
#define fixed3 float3
#define fixed4 float4
#define fixed2x2 float2x2
#define fixed3x3 float3x3
#define fixed4x4 float4x4
#define min16float float
#define min16float2 float2
#define min16float3 float3
#define min16float4 float4
#define min10float float
#define min10float2 float2
#define min10float3 float3
#define min10float4 float4

// Platform: Vulkan, clip depth 0..1 (not reversed), texture v = 0 at the top.
#define UNITY_UV_STARTS_AT_TOP 1
#define UNITY_NEAR_CLIP_VALUE (0.0)
#define SHADER_API_DESKTOP 1
// Projective texture coordinates go to tex2Dproj as they are (a PS Vita
// workaround in Unity).
#define UNITY_PROJ_COORD(a) (a)

// Flow-control attributes.
#define UNITY_BRANCH [branch]
#define UNITY_FLATTEN [flatten]
#define UNITY_UNROLL [unroll]
#define UNITY_UNROLLX(n) [unroll(n)]
#define UNITY_LOOP [loop]

// Constant buffers of a program go to the material set like loose globals.
#define CBUFFER_START(name) cbuffer name {
#define CBUFFER_END };

#define UNITY_INITIALIZE_OUTPUT(type, name) name = (type)0;
#define UNITY_POSITION(pos) float4 pos : SV_POSITION
#define UNITY_VPOS_TYPE float4

// Textures: Unity's "no separate samplers" path.
#define UNITY_DECLARE_TEX2D(tex) sampler2D tex
#define UNITY_DECLARE_TEX2D_NOSAMPLER(tex) sampler2D tex
#define UNITY_DECLARE_TEXCUBE(tex) samplerCUBE tex
#define UNITY_DECLARE_TEXCUBE_NOSAMPLER(tex) samplerCUBE tex
#define UNITY_DECLARE_TEX3D(tex) sampler3D tex
#define UNITY_SAMPLE_TEX2D(tex, coord) tex2D(tex, coord)
#define UNITY_SAMPLE_TEX2D_SAMPLER(tex, samplertex, coord) tex2D(tex, coord)
#define UNITY_SAMPLE_TEX2D_LOD(tex, coord, lod) tex2Dlod(tex, float4(coord, 0, lod))
#define UNITY_SAMPLE_TEXCUBE(tex, coord) texCUBE(tex, coord)
#define UNITY_SAMPLE_TEXCUBE_LOD(tex, coord, lod) texCUBElod(tex, float4(coord, lod))
#define UNITY_SAMPLE_TEXCUBE_SAMPLER(tex, samplertex, coord) texCUBE(tex, coord)
#define UNITY_SAMPLE_TEXCUBE_SAMPLER_LOD(tex, samplertex, coord, lod) texCUBElod(tex, float4(coord, lod))
#define UNITY_SAMPLE_TEX3D(tex, coord) tex3D(tex, coord)
#define UNITY_PASS_TEX2D(tex) tex
#define UNITY_PASS_TEXCUBE(tex) tex
#define UNITY_ARGS_TEX2D(tex) sampler2D tex
#define UNITY_ARGS_TEXCUBE(tex) samplerCUBE tex

#endif // HLSL_SUPPORT_INCLUDED
