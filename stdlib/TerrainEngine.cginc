// facet's terrain engine helpers: the names Unity's terrain detail (grass),
// tree and billboard shaders expect, written from their documented meaning.
//
// The terrain/tree uniforms below are not facet built-ins (docs/binding-model.md):
// they are loose globals, so they land in the program's "$Globals" block
// (material set) and the runtime fills them by name, like material
// properties. Unity keeps them in a cbuffer "UnityTerrain"; a loose global
// is read the same way by shader code.
#ifndef TERRAIN_ENGINE_INCLUDED
#define TERRAIN_ENGINE_INCLUDED

#include "UnityCG.cginc"

// ---- uniforms -----------------------------------------------------------
// grass
fixed4 _WavingTint;          // tint at the crest of a grass wave (rgb)
float4 _WaveAndDistance;     // x = wind time (speed * t), y = wave size, z = wind amount, w = max distance^2
float4 _CameraPosition;      // xyz = camera position (terrain object space), w = 1 / max distance^2
float3 _CameraRight, _CameraUp;  // camera axes for grass billboards

// trees
fixed4 _TreeInstanceColor;
float4 _TreeInstanceScale;       // xyz = per-instance scale
float4x4 _TerrainEngineBendTree; // bend rotation applied by the vertex colour's alpha
float4 _SquashPlaneNormal;       // xyz = plane normal, w = plane offset (object space)
float _SquashAmount;             // 1 = unsquashed, 0 = flattened onto the plane

// tree billboards
float3 _TreeBillboardCameraRight;
float4 _TreeBillboardCameraUp;    // w = billboard offset factor (lift off the ground)
float4 _TreeBillboardCameraFront;
float4 _TreeBillboardCameraPos;   // w = billboard angle factor (0 side view .. 1 top view)
float4 _TreeBillboardDistances;   // x = max distance^2 (z, w: cross-fade start and length, used by some shaders)

// Tree Creator wind: xyz = direction * strength, w = overall amount
float4 _Wind;

// ---- vertex inputs ------------------------------------------------------
struct appdata_tree {
    float4 vertex : POSITION;
    float4 tangent : TANGENT;    // directional ambient occlusion (soft-occlusion trees)
    float3 normal : NORMAL;
    fixed4 color : COLOR;        // w = bend factor
    float4 texcoord : TEXCOORD0;
    UNITY_VERTEX_INPUT_INSTANCE_ID
};

struct appdata_tree_billboard {
    float4 vertex : POSITION;
    fixed4 color : COLOR;
    float4 texcoord : TEXCOORD0;   // uv; y also selects top (> 0) or bottom vertices
    float2 texcoord1 : TEXCOORD1;  // billboard extrusion (x sideways, y upwards)
    UNITY_VERTEX_INPUT_INSTANCE_ID
};

// ---- grass --------------------------------------------------------------

// Sine and cosine of four phases given in cycles 0..1. Unity evaluates a
// truncated Taylor series of the angle (phase * 6.408849 - pi); facet uses
// the exact functions of the same angle.
void FastSinCos(float4 val, out float4 s, out float4 c)
{
    float4 angle = val * 6.408849 - 3.1415927;
    s = sin(angle);
    c = cos(angle);
}

// Moves a grass vertex on the xz plane by four travelling waves and returns
// its colour: tinted towards _WavingTint at the crests (doubled, as Unity's
// detail colours are) and faded out (alpha) towards the detail distance.
fixed4 TerrainWaveGrass(inout float4 vertex, float waveAmount, fixed4 color)
{
    const float4 waveXSize = float4(0.012, 0.02, 0.06, 0.024);
    const float4 waveZSize = float4(0.006, 0.02, 0.02, 0.05);
    const float4 waveSpeed = float4(1.2, 2.0, 1.6, 4.8);
    const float4 waveXMove = float4(0.024, 0.04, -0.12, 0.096);
    const float4 waveZMove = float4(0.006, 0.02, -0.02, 0.1);

    float4 phase = (vertex.x * waveXSize + vertex.z * waveZSize) * _WaveAndDistance.y
                 + _WaveAndDistance.x * waveSpeed;
    float4 s, c;
    FastSinCos(frac(phase), s, c);
    s *= s;
    s *= s;                                   // sin^4: sharp crests

    // Brightness of the wave: a fixed weighting of the four crests.
    float lighting = dot(s, normalize(float4(1, 1, 0.4, 0.2))) * 0.7;

    s *= waveAmount;
    vertex.xz -= float2(dot(s, waveXMove), dot(s, waveZMove)) * _WaveAndDistance.z;

    float3 waveColor = lerp(float3(0.5, 0.5, 0.5), _WavingTint.rgb, lighting);
    float3 toCamera = vertex.xyz - _CameraPosition.xyz;
    color.a = saturate(2.0 * (_WaveAndDistance.w - dot(toCamera, toCamera)) * _CameraPosition.w);
    return fixed4(2.0 * waveColor * color.rgb, color.a);
}

// Extrudes a grass billboard vertex along the camera's right and up axes;
// beyond the detail distance the quad collapses to its anchor point.
void TerrainBillboardGrass(inout float4 pos, float2 offset)
{
    float3 toCamera = pos.xyz - _CameraPosition.xyz;
    if (dot(toCamera, toCamera) > _WaveAndDistance.w)
        offset = 0.0;
    pos.xyz += offset.x * _CameraRight.xyz + offset.y * _CameraUp.xyz;
}

// Mesh grass (appdata_full): colour.a is 1 on top vertices, 0 at the root,
// so only the tops sway.
void WavingGrassVert(inout appdata_full v)
{
    float waveAmount = v.color.a * _WaveAndDistance.z;
    v.color = TerrainWaveGrass(v.vertex, waveAmount, v.color);
}

// Billboard grass: tangent.xy is the extrusion; the upward extrusion is also
// the wave amount, so taller blades sway more.
void WavingGrassBillboardVert(inout appdata_full v)
{
    TerrainBillboardGrass(v.vertex, v.tangent.xy);
    float waveAmount = v.tangent.y;
    v.color = TerrainWaveGrass(v.vertex, waveAmount, v.color);
}

// ---- trees --------------------------------------------------------------

// Pushes a vertex towards the squash plane (n . p + w = 0) by 1 - _SquashAmount.
// The terrain squashes trees this way as they turn into billboards.
inline float4 Squash(in float4 pos)
{
    float3 n = _SquashPlaneNormal.xyz;
    float3 onPlane = pos.xyz - (dot(n, pos.xyz) + _SquashPlaneNormal.w) * n;
    return float4(lerp(onPlane, pos.xyz, _SquashAmount), 1.0);
}

// Instance scale, the terrain's bend (weighted by alpha, the vertex colour's
// w), then squash.
void TerrainAnimateTree(inout float4 pos, float alpha)
{
    pos.xyz *= _TreeInstanceScale.xyz;
    float3 bent = mul(_TerrainEngineBendTree, float4(pos.xyz, 0.0)).xyz;
    pos.xyz = lerp(pos.xyz, bent, alpha);
    pos = Squash(pos);
}

// ---- tree billboards ----------------------------------------------------

// Expands a terrain tree billboard vertex: offset.x along the camera's right
// axis, upwards by a blend of offset.y (side view) and offsetz (top view)
// chosen by the angle factor, and a small push towards the camera (by
// |offset.x|, the same for all four corners) so the quad is not clipped by
// the ground. Beyond the billboard distance the quad collapses.
void TerrainBillboardTree(inout float4 pos, float2 offset, float offsetz)
{
    float3 toCamera = pos.xyz - _TreeBillboardCameraPos.xyz;
    if (dot(toCamera, toCamera) > _TreeBillboardDistances.x)
        offset.xy = offsetz = 0.0;

    float radius = lerp(offset.y, offsetz, _TreeBillboardCameraPos.w);
    pos.xyz += _TreeBillboardCameraRight.xyz * offset.x
             + _TreeBillboardCameraUp.xyz * radius
             + _TreeBillboardCameraFront.xyz * abs(offset.x) * _TreeBillboardCameraUp.w;
}

// ---- Tree Creator -------------------------------------------------------

// Leaf billboards have tangent.w = 0 (1 - |w| = 1): their corner offset is in
// normal.xy and is turned into object space by mat (UNITY_MATRIX_IT_MV,
// i.e. view -> object for directions), and normal/tangent are turned with it.
inline void ExpandBillboard(in float4x4 mat, inout float4 pos, inout float3 normal, inout float4 tangent)
{
    float isBillboard = 1.0f - abs(tangent.w);
    float3 billboardNormal = normalize(mul(float4(normal, 0), mat).xyz);
    float3 billboardTangent = normalize(mul(float4(tangent.xyz, 0), mat).xyz);
    pos += mul(float4(normal.xy, 0, 0), mat) * isBillboard;
    normal = lerp(normal, billboardNormal, isBillboard);
    tangent = lerp(tangent, float4(billboardTangent, -1.0f), isBillboard);
}

// Hermite smoothstep of x in 0..1 (no clamping).
float4 SmoothCurve(float4 x)
{
    return x * x * (3.0 - 2.0 * x);
}

// Triangle wave of period 1: 1 at integers, 0 at half-integers.
// (SpeedTreeWind.cginc defines the same function; whichever comes first wins.)
#ifndef FACET_TRIANGLE_WAVE_DEFINED
#define FACET_TRIANGLE_WAVE_DEFINED
float4 TriangleWave(float4 x)
{
    return abs(frac(x + 0.5) * 2.0 - 1.0);
}
#endif

float4 SmoothTriangleWave(float4 x)
{
    return SmoothCurve(TriangleWave(x));
}

// Tree Creator wind ("detail bending" as in Crytek's vegetation paper):
// animParams = (branch phase, edge flutter, primary bend, secondary bend),
// taken from the vertex colour and uv2. Two smoothed triangle waves per
// motion at fixed frequencies; the object's world position offsets the phase
// so neighbouring trees do not move in step.
inline float4 AnimateVertex(float4 pos, float3 normal, float4 animParams)
{
    const float detailAmp = 0.1f;
    const float branchAmp = 0.3f;

    // (glslang has no matrix swizzles such as ._14_24_34: index the column)
    float3 objPos = float3(unity_ObjectToWorld[0][3], unity_ObjectToWorld[1][3], unity_ObjectToWorld[2][3]);
    float objPhase = objPos.x + objPos.y + objPos.z;
    float branchPhase = objPhase + animParams.x;
    float vertexPhase = dot(pos.xyz, animParams.y + branchPhase);

    // x, y: edge flutter (per vertex); z, w: branch sway (per branch)
    float2 wavesIn = _Time.yy + float2(vertexPhase, branchPhase);
    float4 waves = frac(wavesIn.xxyy * float4(1.975, 0.793, 0.375, 0.193)) * 2.0 - 1.0;
    waves = SmoothTriangleWave(waves);
    float2 wavesSum = waves.xz + waves.yw;

    float3 bend = animParams.y * detailAmp * normal.xyz;   // edges flutter along the normal
    bend.y = animParams.w * branchAmp;                       // branches bob up and down
    pos.xyz += (wavesSum.xyx * bend + _Wind.xyz * wavesSum.y * animParams.w) * _Wind.w;

    // primary bending: the whole tree leans with the wind
    pos.xyz += animParams.z * _Wind.xyz;
    return pos;
}

#endif // TERRAIN_ENGINE_INCLUDED
