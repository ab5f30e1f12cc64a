// The precision-mangled resource types of Unity's HLSLcc path
// (Texture2D_half, sampler2D_float, ...). Unity's own HLSLSupport.cginc
// declares textures with them when UNITY_COMPILER_HLSLCC is defined, as it is
// for Vulkan; glslang has no such types, and on Vulkan the precision suffix
// changes nothing, so each is its plain type. Included before HLSLSupport in
// every CGPROGRAM, so that Unity's CGIncludes (facetc -I) compile unchanged.
#ifndef FACET_HLSLCC_TYPES_INCLUDED
#define FACET_HLSLCC_TYPES_INCLUDED

#define Texture2D_half Texture2D
#define Texture2D_float Texture2D
#define Texture3D_half Texture3D
#define Texture3D_float Texture3D
#define TextureCube_half TextureCube
#define TextureCube_float TextureCube
#define Texture2DArray_half Texture2DArray
#define Texture2DArray_float Texture2DArray
#define TextureCubeArray_half TextureCubeArray
#define TextureCubeArray_float TextureCubeArray
#define Texture2DMS_half Texture2DMS
#define Texture2DMS_float Texture2DMS
#if !defined(sampler2D_half)
#define sampler1D_half sampler1D
#define sampler1D_float sampler1D
#define sampler2D_half sampler2D
#define sampler2D_float sampler2D
#define sampler3D_half sampler3D
#define sampler3D_float sampler3D
#define samplerCUBE_half samplerCUBE
#define samplerCUBE_float samplerCUBE
#endif

// glslang knows min16float and its vectors, not its matrices (Unity's half3x3
// on Vulkan).
#define min16float1x1 float1x1
#define min16float1x2 float1x2
#define min16float1x3 float1x3
#define min16float1x4 float1x4
#define min16float2x1 float2x1
#define min16float2x2 float2x2
#define min16float2x3 float2x3
#define min16float2x4 float2x4
#define min16float3x1 float3x1
#define min16float3x2 float3x2
#define min16float3x3 float3x3
#define min16float3x4 float3x4
#define min16float4x1 float4x1
#define min16float4x2 float4x2
#define min16float4x3 float4x3
#define min16float4x4 float4x4
#define min10float1x1 float1x1
#define min10float1x2 float1x2
#define min10float1x3 float1x3
#define min10float1x4 float1x4
#define min10float2x1 float2x1
#define min10float2x2 float2x2
#define min10float2x3 float2x3
#define min10float2x4 float2x4
#define min10float3x1 float3x1
#define min10float3x2 float3x2
#define min10float3x3 float3x3
#define min10float3x4 float3x4
#define min10float4x1 float4x1
#define min10float4x2 float4x2
#define min10float4x3 float4x3
#define min10float4x4 float4x4

#endif  // FACET_HLSLCC_TYPES_INCLUDED
