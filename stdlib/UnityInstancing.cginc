// GPU instancing and single-pass stereo are not implemented in facet: these
// macros expand to what Unity gives when both are off, so code written for
// them compiles unchanged. INSTANCING_ON has no effect.
#ifndef UNITY_INSTANCING_INCLUDED
#define UNITY_INSTANCING_INCLUDED

#define UNITY_VERTEX_INPUT_INSTANCE_ID
#define UNITY_GET_INSTANCE_ID(input) 0
#define UNITY_SETUP_INSTANCE_ID(input)
#define UNITY_TRANSFER_INSTANCE_ID(input, output)
#define UNITY_INSTANCING_BUFFER_START(name)
#define UNITY_INSTANCING_BUFFER_END(name)
#define UNITY_INSTANCING_CBUFFER_START(name)
#define UNITY_INSTANCING_CBUFFER_END
#define UNITY_DEFINE_INSTANCED_PROP(type, var) type var;
#define UNITY_ACCESS_INSTANCED_PROP(buffer, var) var

#define UNITY_VERTEX_OUTPUT_STEREO
#define UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO(output)
#define UNITY_TRANSFER_VERTEX_OUTPUT_STEREO(input, output)
#define UNITY_SETUP_STEREO_EYE_INDEX_POST_VERTEX(input)

#endif // UNITY_INSTANCING_INCLUDED
