// GPU instancing and single-pass stereo are not implemented in facet: these
// macros expand to what Unity gives when both are off, so code written for
// them compiles unchanged. INSTANCING_ON has no effect: UNITY_INSTANCING_ENABLED,
// UNITY_PROCEDURAL_INSTANCING_ENABLED and UNITY_STEREO_INSTANCING_ENABLED stay
// undefined. Instanced properties are plain material uniforms ("$Globals").
// UNITY_ACCESS_INSTANCED_PROP takes Unity 2017.4+'s two arguments (buffer,
// name); the one-argument form of 5.6/2017.1 cannot share the name (glslang
// has no variadic macros).
#ifndef UNITY_INSTANCING_INCLUDED
#define UNITY_INSTANCING_INCLUDED

#define UNITY_SUPPORT_INSTANCING
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
