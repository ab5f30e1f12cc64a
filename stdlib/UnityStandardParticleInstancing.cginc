// Procedural particle instancing (UNITY_PARTICLE_INSTANCING_ENABLED) is not
// implemented in facet: UNITY_PROCEDURAL_INSTANCING_ENABLED is never
// defined, so particles are plain meshes and these hooks are the no-op
// forms that the particle shaders call (vertInstancingSetup is the
// `instancing_options procedural:` function).
#ifndef UNITY_STANDARD_PARTICLE_INSTANCING_INCLUDED
#define UNITY_STANDARD_PARTICLE_INSTANCING_INCLUDED

#include "UnityCG.cginc"

void vertInstancingSetup() {}
void vertInstancingColor(inout fixed4 color) {}
void vertInstancingUVs(in float2 uv, out float2 texcoord, out float3 texcoord2AndBlend)
{
    texcoord = uv;
    texcoord2AndBlend = float3(uv, 0.0);
}
void vertInstancingUVs(in float2 uv, out float2 texcoord) { texcoord = uv; }

#endif // UNITY_STANDARD_PARTICLE_INSTANCING_INCLUDED
