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

// 2D and cube textures: Unity's separate-sampler path (Direct3D 11, Vulkan,
// Metal): a texture object plus a sampler named sampler<tex>, so code may
// pass either on (`_MainTex.SampleGrad(sampler_MainTex, ...)`, one sampler
// for several textures, `IsEmpty(TextureCube)` overloads on
// unity_SpecCube0). 3D textures keep the combined DX9 form.
#define UNITY_DECLARE_TEX2D(tex) Texture2D tex; SamplerState sampler##tex
#define UNITY_DECLARE_TEX2D_NOSAMPLER(tex) Texture2D tex
#define UNITY_DECLARE_TEXCUBE(tex) TextureCube tex; SamplerState sampler##tex
#define UNITY_DECLARE_TEXCUBE_NOSAMPLER(tex) TextureCube tex
#define UNITY_DECLARE_TEX3D(tex) sampler3D tex
// Sampling goes through overloads, so that combined samplers sample too:
// the frame's 2D built-ins (unity_Lightmap, unity_ShadowMask, ...: their
// sampler<tex> names the texture itself, FacetBuiltins.hlsl), and a
// program's own `samplerCUBE _Cube; #define sampler_Cube _Cube`.
float4 FacetSampleTex2D(Texture2D tex, SamplerState s, float2 uv) { return tex.Sample(s, uv); }
float4 FacetSampleTex2D(sampler2D tex, sampler2D s, float2 uv) { return tex2D(tex, uv); }
float4 FacetSampleTex2DLod(Texture2D tex, SamplerState s, float2 uv, float lod) { return tex.SampleLevel(s, uv, lod); }
float4 FacetSampleTex2DLod(sampler2D tex, sampler2D s, float2 uv, float lod) { return tex2Dlod(tex, float4(uv, 0, lod)); }
float4 FacetSampleTexCube(TextureCube tex, SamplerState s, float3 dir) { return tex.Sample(s, dir); }
float4 FacetSampleTexCube(samplerCUBE tex, samplerCUBE s, float3 dir) { return texCUBE(tex, dir); }
float4 FacetSampleTexCubeLod(TextureCube tex, SamplerState s, float3 dir, float lod) { return tex.SampleLevel(s, dir, lod); }
float4 FacetSampleTexCubeLod(samplerCUBE tex, samplerCUBE s, float3 dir, float lod) { return texCUBElod(tex, float4(dir, lod)); }
#define UNITY_SAMPLE_TEX2D(tex, coord) FacetSampleTex2D(tex, sampler##tex, coord)
#define UNITY_SAMPLE_TEX2D_SAMPLER(tex, samplertex, coord) FacetSampleTex2D(tex, sampler##samplertex, coord)
#define UNITY_SAMPLE_TEX2D_LOD(tex, coord, lod) FacetSampleTex2DLod(tex, sampler##tex, coord, lod)
#define UNITY_SAMPLE_TEX2D_SAMPLER_LOD(tex, samplertex, coord, lod) FacetSampleTex2DLod(tex, sampler##samplertex, coord, lod)
#define UNITY_SAMPLE_TEXCUBE(tex, coord) FacetSampleTexCube(tex, sampler##tex, coord)
#define UNITY_SAMPLE_TEXCUBE_LOD(tex, coord, lod) FacetSampleTexCubeLod(tex, sampler##tex, coord, lod)
#define UNITY_SAMPLE_TEXCUBE_SAMPLER(tex, samplertex, coord) FacetSampleTexCube(tex, sampler##samplertex, coord)
#define UNITY_SAMPLE_TEXCUBE_SAMPLER_LOD(tex, samplertex, coord, lod) FacetSampleTexCubeLod(tex, sampler##samplertex, coord, lod)
#define UNITY_SAMPLE_TEX3D(tex, coord) tex3D(tex, coord)
#define UNITY_PASS_TEX2D(tex) tex, sampler##tex
#define UNITY_PASS_TEXCUBE(tex) tex, sampler##tex
#define UNITY_PASS_TEXCUBE_SAMPLER(tex, samplertex) tex, sampler##samplertex
#define UNITY_PASS_TEXCUBE_SAMPLER_LOD(tex, samplertex, lod) tex, sampler##samplertex, lod
#define UNITY_ARGS_TEX2D(tex) Texture2D tex, SamplerState sampler##tex
#define UNITY_ARGS_TEXCUBE(tex) TextureCube tex, SamplerState sampler##tex

// fxc still reads Direct3D 9 effect files' lower-case texture types
// (`texture2D _OutlineTexture;`), which glslang does not know.
#define texture2D Texture2D
#define texture3D Texture3D
#define textureCUBE TextureCube

// Precision-suffixed sampler and texture types are the plain ones (all
// sampling is float).
#define sampler2D_float sampler2D
#define samplerCUBE_float samplerCUBE
#define sampler3D_float sampler3D
#define Texture2D_float Texture2D
#define Texture2DArray_float Texture2DArray
#define Texture2DMS_float Texture2DMS
#define TextureCube_float TextureCube
#define TextureCubeArray_float TextureCubeArray
#define Texture3D_float Texture3D
#define sampler2D_half sampler2D
#define samplerCUBE_half samplerCUBE
#define sampler3D_half sampler3D
#define Texture2D_half Texture2D
#define Texture2DArray_half Texture2DArray
#define Texture2DMS_half Texture2DMS
#define TextureCube_half TextureCube
#define TextureCubeArray_half TextureCubeArray
#define Texture3D_half Texture3D
#define UNITY_DECLARE_TEX2D_HALF(tex) Texture2D tex; SamplerState sampler##tex
#define UNITY_DECLARE_TEX2D_FLOAT(tex) Texture2D tex; SamplerState sampler##tex
#define UNITY_DECLARE_TEX2D_NOSAMPLER_HALF(tex) Texture2D tex
#define UNITY_DECLARE_TEX2D_NOSAMPLER_FLOAT(tex) Texture2D tex
#define UNITY_DECLARE_TEX2D_NOSAMPLER_INT(tex) Texture2D<int4> tex
#define UNITY_DECLARE_TEX2D_NOSAMPLER_UINT(tex) Texture2D<uint4> tex
#define UNITY_DECLARE_TEX3D_NOSAMPLER(tex) sampler3D tex
#define UNITY_DECLARE_TEX3D_FLOAT(tex) sampler3D tex
#define UNITY_DECLARE_TEX3D_HALF(tex) sampler3D tex
#define UNITY_SAMPLE_TEX3D_LOD(tex, coord, lod) tex3Dlod(tex, float4(coord, lod))
#define UNITY_SAMPLE_TEX3D_SAMPLER(tex, samplertex, coord) tex3D(tex, coord)
#define UNITY_SAMPLE_TEX3D_SAMPLER_LOD(tex, samplertex, coord, lod) tex3Dlod(tex, float4(coord, lod))
#define SampleCubeReflection(env, dir, lod) UNITY_SAMPLE_TEXCUBE_LOD(env, dir, lod)
#define samplerRECT sampler2D
#define texRECT tex2D
#define texRECTlod tex2Dlod
#define texRECTbias tex2Dbias
#define texRECTproj tex2Dproj

// 2D and cube arrays have no combined DX9 form: a texture object plus a
// sampler named sampler<tex> (two descriptors), as Unity's DX11 path.
#define UNITY_DECLARE_TEX2DARRAY(tex) Texture2DArray tex; SamplerState sampler##tex
#define UNITY_DECLARE_TEX2DARRAY_NOSAMPLER(tex) Texture2DArray tex
#define UNITY_DECLARE_TEX2DARRAY_MS(tex) Texture2DMSArray<float> tex; SamplerState sampler##tex
#define UNITY_DECLARE_TEX2DARRAY_MS_NOSAMPLER(tex) Texture2DArray<float> tex
#define UNITY_ARGS_TEX2DARRAY(tex) Texture2DArray tex, SamplerState sampler##tex
#define UNITY_PASS_TEX2DARRAY(tex) tex, sampler##tex
#define UNITY_SAMPLE_TEX2DARRAY(tex, coord) tex.Sample(sampler##tex, coord)
#define UNITY_SAMPLE_TEX2DARRAY_LOD(tex, coord, lod) tex.SampleLevel(sampler##tex, coord, lod)
#define UNITY_SAMPLE_TEX2DARRAY_SAMPLER(tex, samplertex, coord) tex.Sample(sampler##samplertex, coord)
#define UNITY_SAMPLE_TEX2DARRAY_SAMPLER_LOD(tex, samplertex, coord, lod) tex.SampleLevel(sampler##samplertex, coord, lod)
#define UNITY_DECLARE_TEXCUBEARRAY(tex) TextureCubeArray tex; SamplerState sampler##tex
#define UNITY_DECLARE_TEXCUBEARRAY_NOSAMPLER(tex) TextureCubeArray tex
#define UNITY_ARGS_TEXCUBEARRAY(tex) TextureCubeArray tex, SamplerState sampler##tex
#define UNITY_PASS_TEXCUBEARRAY(tex) tex, sampler##tex
#define UNITY_SAMPLE_TEXCUBEARRAY(tex, coord) tex.Sample(sampler##tex, coord)
#define UNITY_SAMPLE_TEXCUBEARRAY_LOD(tex, coord, lod) tex.SampleLevel(sampler##tex, coord, lod)
#define UNITY_SAMPLE_TEXCUBEARRAY_SAMPLER(tex, samplertex, coord) tex.Sample(sampler##samplertex, coord)
#define UNITY_SAMPLE_TEXCUBEARRAY_SAMPLER_LOD(tex, samplertex, coord, lod) tex.SampleLevel(sampler##samplertex, coord, lod)

// Depth textures (the camera's depth: declare _CameraDepthTexture with
// these, the runtime binds it by name). Depth is in .r.
#define UNITY_DECLARE_DEPTH_TEXTURE(tex) sampler2D tex
#define UNITY_DECLARE_DEPTH_TEXTURE_MS(tex) Texture2DMS<float> tex
#define SAMPLE_DEPTH_TEXTURE(tex, uv) (tex2D(tex, uv).r)
#define SAMPLE_DEPTH_TEXTURE_PROJ(tex, uv) (tex2Dproj(tex, uv).r)
#define SAMPLE_DEPTH_TEXTURE_LOD(tex, uv) (tex2Dlod(tex, uv).r)
#define SAMPLE_RAW_DEPTH_TEXTURE(tex, uv) (tex2D(tex, uv))
#define SAMPLE_RAW_DEPTH_TEXTURE_PROJ(tex, uv) (tex2Dproj(tex, uv))
#define SAMPLE_RAW_DEPTH_TEXTURE_LOD(tex, uv) (tex2Dlod(tex, uv))
#define SAMPLE_DEPTH_CUBE_TEXTURE(tex, uv) (texCUBE(tex, uv).r)
#define UNITY_SAMPLE_DEPTH(value) (value).r
// Screen-space textures are plain 2D textures (no single-pass stereo arrays).
#define UNITY_DECLARE_SCREENSPACE_TEXTURE(tex) sampler2D tex;  // with its ";", as Unity has it
#define UNITY_DECLARE_SCREENSPACE_SHADOWMAP(tex) sampler2D tex
#define UNITY_SAMPLE_SCREENSPACE_TEXTURE(tex, uv) tex2D(tex, uv)
#define UNITY_SAMPLE_SCREEN_SHADOW(tex, uv) tex2Dproj(tex, UNITY_PROJ_COORD(uv)).r
// Shadow maps: a depth texture compared by hand (1 lit, 0 shadowed).
#define UNITY_DECLARE_SHADOWMAP(tex) sampler2D tex
#define UNITY_DECLARE_TEXCUBE_SHADOWMAP(tex) samplerCUBE tex
#define UNITY_SAMPLE_SHADOW(tex, coord) (tex2Dlod(tex, float4((coord).xy, 0, 0)).r >= (coord).z ? 1.0 : 0.0)
#define UNITY_SAMPLE_SHADOW_PROJ(tex, coord) UNITY_SAMPLE_SHADOW(tex, (coord).xyz / (coord).w)
#define UNITY_SAMPLE_TEXCUBE_SHADOW(tex, coord) (texCUBElod(tex, float4((coord).xyz, 0)).r >= (coord).w ? 1.0 : 0.0)
// Old single-channel alpha textures.
#define UNITY_SAMPLE_1CHANNEL(x, y) tex2D(x, y).a
#define UNITY_ALPHA_CHANNEL a
// The channel of Unity's light falloff textures.
#define UNITY_ATTEN_CHANNEL r

// Framebuffer fetch is not available: inputs are textures read at the
// pixel position.
#define UNITY_DECLARE_FRAMEBUFFER_INPUT_FLOAT(idx) Texture2D<float4> _UnityFBInput##idx
#define UNITY_DECLARE_FRAMEBUFFER_INPUT_HALF(idx) Texture2D<float4> _UnityFBInput##idx
#define UNITY_DECLARE_FRAMEBUFFER_INPUT_INT(idx) Texture2D<int4> _UnityFBInput##idx
#define UNITY_DECLARE_FRAMEBUFFER_INPUT_UINT(idx) Texture2D<uint4> _UnityFBInput##idx
#define UNITY_READ_FRAMEBUFFER_INPUT(idx, v2fname) _UnityFBInput##idx.Load(uint3((v2fname).xy, 0))

// Tessellation and keyword defaults (UNITY_COMPILER_HLSL comes from the
// prelude, as Unity's compiler defines it).
#define UNITY_CAN_COMPILE_TESSELLATION 1
// Where a shader turns no lightmap keyword on, the _OFF forms hold.
#if !defined(LIGHTMAP_ON) && !defined(LIGHTMAP_OFF)
#define LIGHTMAP_OFF 1
#endif
#if !defined(DYNAMICLIGHTMAP_ON) && !defined(DYNAMICLIGHTMAP_OFF)
#define DYNAMICLIGHTMAP_OFF 1
#endif
#if !defined(DIRLIGHTMAP_COMBINED) && !defined(DIRLIGHTMAP_OFF)
#define DIRLIGHTMAP_OFF 1
#endif
// Tessellation attribute names pass through unchanged.
#define UNITY_outputcontrolpoints outputcontrolpoints
#define UNITY_outputtopology outputtopology
#define UNITY_partitioning partitioning
#define UNITY_patchconstantfunc patchconstantfunc
#define UNITY_domain domain
#define UNITY_ALLOWED_MRT_COUNT 8
#define UNITY_FASTOPT
// Cg's WPOS is VPOS (the pixel position).
#define WPOS VPOS
#define GLOBAL_CBUFFER_START(name) cbuffer name {
#define GLOBAL_CBUFFER_END };
#define CBUFFER_START_WITH_BINDING(name) cbuffer name {

#endif // HLSL_SUPPORT_INCLUDED
