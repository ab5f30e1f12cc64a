// GPU instancing as Unity's UnityInstancing.cginc gives it: with
// INSTANCING_ON (multi_compile_instancing, and a material with instancing
// enabled) UNITY_INSTANCING_ENABLED is defined, the vertex input's
// SV_InstanceID picks this instance's entry of the per-instance arrays, and
// unity_ObjectToWorld / unity_WorldToObject read the instance's matrices
// from the per-draw set (set 3, binding 9). A buffer of
// UNITY_INSTANCING_BUFFER_START(Props) is a cbuffer "UnityInstancing_Props"
// of one struct per instance (material set); the renderer fills element i
// of every such array from the i-th object of the instanced draw, by member
// name (docs/rendering.md, "GPU instancing"). Without INSTANCING_ON the
// macros expand to what Unity gives when instancing is off, and instanced
// properties are plain material uniforms ("$Globals"). Single-pass stereo
// stays off, as facet renders one view: its macros are the non-stereo ones.
// UNITY_ACCESS_INSTANCED_PROP takes Unity 2017.4+'s two arguments (buffer,
// name); the one-argument form of 5.6/2017.1 cannot share the name (glslang
// has no variadic macros).
#ifndef UNITY_INSTANCING_INCLUDED
#define UNITY_INSTANCING_INCLUDED

#define UNITY_SUPPORT_INSTANCING
#if defined(INSTANCING_ON)
    #define UNITY_INSTANCING_ENABLED
#endif

#if defined(UNITY_INSTANCING_ENABLED)
// 128 instances a draw: two matrices each fill Vulkan's guaranteed 16 KiB
// of a uniform buffer (maxUniformBufferRange).
#define UNITY_INSTANCED_ARRAY_SIZE 128
#define UNITY_MAX_INSTANCE_COUNT UNITY_INSTANCED_ARRAY_SIZE
static const uint unity_BaseInstanceID = 0;
static const uint unity_InstanceCount = UNITY_INSTANCED_ARRAY_SIZE;
static uint unity_InstanceID;

#define DEFAULT_UNITY_VERTEX_INPUT_INSTANCE_ID uint instanceID : SV_InstanceID;
#define UNITY_VERTEX_INPUT_INSTANCE_ID DEFAULT_UNITY_VERTEX_INPUT_INSTANCE_ID
#define UNITY_GET_INSTANCE_ID(input) input.instanceID
#define DEFAULT_UNITY_SETUP_INSTANCE_ID(input) { unity_InstanceID = UNITY_GET_INSTANCE_ID(input) + unity_BaseInstanceID; }
#define UNITY_SETUP_INSTANCE_ID(input) DEFAULT_UNITY_SETUP_INSTANCE_ID(input)
#define UNITY_TRANSFER_INSTANCE_ID(input, output) output.instanceID = UNITY_GET_INSTANCE_ID(input)
#define UNITY_INSTANCING_BUFFER_START(buf) cbuffer UnityInstancing_##buf { struct {
#define UNITY_INSTANCING_BUFFER_END(arr) } arr##Array[UNITY_INSTANCED_ARRAY_SIZE]; };
#define UNITY_INSTANCING_CBUFFER_START(name) UNITY_INSTANCING_BUFFER_START(name)
#define UNITY_INSTANCING_CBUFFER_END UNITY_INSTANCING_BUFFER_END(unity)
#define UNITY_INSTANCING_CBUFFER_SCOPE_BEGIN(name) UNITY_INSTANCING_BUFFER_START(name)
#define UNITY_INSTANCING_CBUFFER_SCOPE_END UNITY_INSTANCING_BUFFER_END(unity)
#define UNITY_DEFINE_INSTANCED_PROP(type, var) type var;
#define UNITY_ACCESS_INSTANCED_PROP(arr, var) arr##Array[unity_InstanceID].var
#define UNITY_ACCESS_MERGED_INSTANCED_PROP(arr, var) arr##Array[unity_InstanceID].var

// The per-instance built-ins, after FacetBuiltins.hlsl declared the per-draw
// ones: from here on the names read the instance's entry.
cbuffer UnityInstancing_PerDraw0 : register(b9, space3)
{
    struct {
        float4x4 unity_ObjectToWorldArray;
        float4x4 unity_WorldToObjectArray;
    } unity_Builtins0Array[UNITY_INSTANCED_ARRAY_SIZE];
};
#define unity_ObjectToWorld unity_Builtins0Array[unity_InstanceID].unity_ObjectToWorldArray
#define unity_WorldToObject unity_Builtins0Array[unity_InstanceID].unity_WorldToObjectArray
#define UnityObjectToClipPosInstanced(pos) UnityObjectToClipPos(pos)
#else
#define UNITY_INSTANCED_ARRAY_SIZE 1
#define UNITY_MAX_INSTANCE_COUNT 1
static const uint unity_BaseInstanceID = 0;
static const uint unity_InstanceCount = 1;

#define DEFAULT_UNITY_VERTEX_INPUT_INSTANCE_ID
#define UNITY_VERTEX_INPUT_INSTANCE_ID
#define UNITY_GET_INSTANCE_ID(input) 0
#define DEFAULT_UNITY_SETUP_INSTANCE_ID(input)
#define UNITY_SETUP_INSTANCE_ID(input)
#define UNITY_TRANSFER_INSTANCE_ID(input, output)
#define UNITY_INSTANCING_BUFFER_START(name)
#define UNITY_INSTANCING_BUFFER_END(name)
#define UNITY_INSTANCING_CBUFFER_START(name)
#define UNITY_INSTANCING_CBUFFER_END
#define UNITY_INSTANCING_CBUFFER_SCOPE_BEGIN(name) CBUFFER_START(name)
#define UNITY_INSTANCING_CBUFFER_SCOPE_END CBUFFER_END
#define UNITY_DEFINE_INSTANCED_PROP(type, var) type var;
#define UNITY_ACCESS_INSTANCED_PROP(buffer, var) var
#define UNITY_ACCESS_MERGED_INSTANCED_PROP(buffer, var) var
#define UnityObjectToClipPosInstanced(pos) UnityObjectToClipPos(pos)
#endif

#define DEFAULT_UNITY_VERTEX_OUTPUT_STEREO
#define UNITY_VERTEX_OUTPUT_STEREO
#define DEFAULT_UNITY_VERTEX_OUTPUT_STEREO_EYE_INDEX
#define UNITY_VERTEX_OUTPUT_STEREO_EYE_INDEX
#define DEFAULT_UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO(output)
#define UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO(output)
#define DEFAULT_UNITY_INITIALIZE_OUTPUT_STEREO_EYE_INDEX(output)
#define UNITY_INITIALIZE_OUTPUT_STEREO_EYE_INDEX(output)
#define DEFAULT_UNITY_TRANSFER_VERTEX_OUTPUT_STEREO(input, output)
#define UNITY_TRANSFER_VERTEX_OUTPUT_STEREO(input, output)
#define DEFAULT_UNITY_SETUP_STEREO_EYE_INDEX_POST_VERTEX(input)
#define UNITY_SETUP_STEREO_EYE_INDEX_POST_VERTEX(input)

#endif // UNITY_INSTANCING_INCLUDED
