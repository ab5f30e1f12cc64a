// The "simple" forward path (UNITY_STANDARD_SIMPLE) under its names. facet
// does not keep a second, cheaper implementation: these are the full path's
// functions and structs (UnityStandardCore.cginc) renamed, so shaders and
// overrides that name the simple forms compile and shade like the full path.
#ifndef UNITY_STANDARD_CORE_FORWARD_SIMPLE_INCLUDED
#define UNITY_STANDARD_CORE_FORWARD_SIMPLE_INCLUDED

#include "UnityStandardCore.cginc"

#define VertexOutputBaseSimple VertexOutputForwardBase
#define VertexOutputForwardAddSimple VertexOutputForwardAdd

VertexOutputBaseSimple vertForwardBaseSimple(VertexInput v) { return vertForwardBase(v); }
half4 fragForwardBaseSimpleInternal(VertexOutputBaseSimple i) { return fragForwardBaseInternal(i); }
half4 fragForwardBaseSimple(VertexOutputBaseSimple i) : SV_Target { return fragForwardBaseSimpleInternal(i); }

VertexOutputForwardAddSimple vertForwardAddSimple(VertexInput v) { return vertForwardAdd(v); }
half4 fragForwardAddSimpleInternal(VertexOutputForwardAddSimple i) { return fragForwardAddInternal(i); }
half4 fragForwardAddSimple(VertexOutputForwardAddSimple i) : SV_Target { return fragForwardAddSimpleInternal(i); }

#endif // UNITY_STANDARD_CORE_FORWARD_SIMPLE_INCLUDED
