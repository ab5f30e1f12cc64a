// facet's SpeedTree wind, under the names of Unity's SpeedTreeWind.cginc.
//
// Two wind models:
//  - SpeedTree 7/8 wind (the default, and with SPEEDTREE_8_WIND): global sway
//    of the whole tree, branch oscillation with twitch/whip/turbulence,
//    leaf ripple and tumble/twitch, and palm frond ripple, all driven by
//    the _ST_Wind* uniforms the engine animates every frame (their .x
//    components carry the accumulated wind time of each effect).
//  - SpeedTree 9 wind (SPEEDTREE_9_WIND, Unity 6's SpeedTree9 shader):
//    noise-driven shared (trunk), two branch levels and leaf ripple, from
//    the _ST_*_NoisePosTurbulence_Independence etc. uniforms.
// Unity 6's file picks 9 when neither is defined; facet keeps 7/8 as the
// default because the older shaders include this file without defining either.
//
// The uniforms are not facet built-ins: they are loose globals ("$Globals",
// material set), filled by name. Unity keeps them in a cbuffer
// "SpeedTreeWind"; shader code reads them the same way.
#ifndef SPEEDTREE_WIND_INCLUDED
#define SPEEDTREE_WIND_INCLUDED

#if !defined(SPEEDTREE_9_WIND)
    #define SPEEDTREE_9_WIND 0
#endif
#if !defined(SPEEDTREE_8_WIND)
    #define SPEEDTREE_8_WIND (!SPEEDTREE_9_WIND)
#endif

float4 _ST_WindVector;   // xyz = world wind direction; v7/8: w = strength, v9: w = strength

#if SPEEDTREE_8_WIND
///////////////////////////////////////////////////////////////////////////////
// SpeedTree 7/8 wind

float4 _ST_WindGlobal;            // x = time, y = distance, z = 1/tree height, w = height exponent
float4 _ST_WindBranch;            // x = time, y = distance
float4 _ST_WindBranchTwitch;      // x = amount, y = frequency scale
float4 _ST_WindBranchWhip;        // x = whip amount
float4 _ST_WindBranchAnchor;      // xyz = anchor direction, w = distance
float4 _ST_WindBranchAdherences;  // x = global (trunk) adherence, y = branch adherence
float4 _ST_WindTurbulences;       // x = branch turbulence
float4 _ST_WindLeaf1Ripple;       // x = time, y = amount
float4 _ST_WindLeaf1Tumble;       // x = time, y = flip, z = twist, w = adherence
float4 _ST_WindLeaf1Twitch;       // x = amount, y = sharpness, z = time
float4 _ST_WindLeaf2Ripple;
float4 _ST_WindLeaf2Tumble;
float4 _ST_WindLeaf2Twitch;
float4 _ST_WindFrondRipple;       // x = time, y = distance, z = tile, w = lighting adjust
float4 _ST_WindAnimation;         // x = global time (turbulence)

// A direction packed into one float as three base-16 digits (x in the
// highest, z in the lowest place), each 0..1 mapped to -1..1.
float3 UnpackNormalFromFloat(float fValue)
{
    float3 digits = frac(fValue / float3(16.0, 1.0, 0.0625));
    return digits * 2.0 - 1.0;
}

// Hermite smoothstep without clamping.
float4 CubicSmooth(float4 vData)
{
    return vData * vData * (3.0 - 2.0 * vData);
}

// Period-1 triangle wave, 1 at integers and 0 at half-integers.
// (TerrainEngine.cginc defines the same function; whichever comes first wins.)
#ifndef FACET_TRIANGLE_WAVE_DEFINED
#define FACET_TRIANGLE_WAVE_DEFINED
float4 TriangleWave(float4 vData)
{
    return abs(frac(vData + 0.5) * 2.0 - 1.0);
}
#endif

// A cheap sine-like wave (period 1, range -1..1): a smoothed triangle wave.
float4 TrigApproximate(float4 vData)
{
    return (CubicSmooth(TriangleWave(vData)) - 0.5) * 2.0;
}

// Rotation by fAngle (radians, right-handed) about the unit axis vAxis, for
// mul(R, v): Rodrigues' formula c*I + s*[axis]x + (1 - c)*axis*axis^T.
float3x3 RotationMatrix(float3 vAxis, float fAngle)
{
    float s, c;
    sincos(fAngle, s, c);
    float3 a = vAxis;
    float3x3 skew = float3x3(0, -a.z, a.y,
                             a.z, 0, -a.x,
                             -a.y, a.x, 0);
    float3x3 outer = float3x3(a * a.x, a * a.y, a * a.z);   // symmetric: rows = columns
    return float3x3(c, 0, 0, 0, c, 0, 0, 0, c) + s * skew + (1.0 - c) * outer;
}

float3x3 mul_float3x3_float3x3(float3x3 mMatrixA, float3x3 mMatrixB) { return mul(mMatrixA, mMatrixB); }
float3 mul_float3x3_float3(float3x3 mMatrix, float3 vVector) { return mul(mMatrix, vVector); }

// cross() with SpeedTree's argument order (GLSL ports swap them).
#define wind_cross(a, b) cross((a), (b))

// Scales fCurrent between fMinScale and fMaxScale by a wave travelling along
// the wind (rolling gusts).
float Roll(float fCurrent, float fMaxScale, float fMinScale, float fSpeed, float fRipple,
           float3 vPos, float fTime, float3 vRotatedWindVector)
{
    float windAngle = dot(vPos, -vRotatedWindVector) * fRipple;
    float adjust = (TrigApproximate(float4(windAngle + fTime * fSpeed, 0, 0, 0)).x + 1.0) * 0.5;
    return lerp(fCurrent * fMinScale, fCurrent * fMaxScale, adjust);
}

// Occasional sharp jerks: the product of two waves (one at 0.87 of the
// other's rate), mapped to 0..1 and sharpened by a power.
float Twitch(float3 vPos, float fAmount, float fSharpness, float fTime)
{
    float4 osc = TrigApproximate(float4(fTime + (vPos.x + vPos.z), 0.87 * fTime + vPos.y, 0, 0));
    float twitch = (osc.x * osc.y * osc.y + 1.0) * 0.5;
    return fAmount * pow(saturate(twitch), fSharpness);
}

// Branch oscillation. Complex: a fine wave mixed with a broad one (the
// product of two waves, pushed towards +-1) by the twitch amount, the broad
// part fading as the wind gets stronger (_ST_WindVector.w). Simple: two
// waves at a 0.689 ratio. With whip, a fourth wave that lags by the branch
// weight scales the result; vOscillations returns the waves for the caller.
float Oscillate(float3 vPos, float fTime, float fOffset, float fWeight, float fWhip,
                bool bWhip, bool bRoll, bool bComplex, float fTwitch, float fTwitchFreqScale,
                inout float4 vOscillations, float3 vRotatedWindVector)
{
    float t = fTime + fOffset;
    float whipPhase = bWhip ? t + (1.0 - fWeight) : 0.0;
    float oscillation;
    if (bComplex)
    {
        vOscillations = TrigApproximate(float4(t, fTime * fTwitchFreqScale + fOffset, fTwitchFreqScale * 0.5 * t, whipPhase));
        float fine = vOscillations.x;
        float broad = vOscillations.y * vOscillations.z;
        float target = broad < 0.0 ? -1.0 : 1.0;
        float amount = abs(broad);
        broad = lerp(broad, target, amount);
        broad = lerp(broad, target, amount);
        oscillation = broad * fTwitch * (1.0 - _ST_WindVector.w) + fine * (1.0 - fTwitch);
    }
    else
    {
        vOscillations = TrigApproximate(float4(t, fTime * 0.689 + fOffset, 0.0, whipPhase));
        oscillation = vOscillations.x + vOscillations.y * vOscillations.x;
    }
    if (bWhip)
        oscillation *= 1.0 + vOscillations.w * fWhip;
    return oscillation;
}

// Slow gusts that reduce a branch's adherence to the wind direction.
float Turbulence(float fTime, float fOffset, float fGlobalTime, float fTurbulence)
{
    float4 osc = TrigApproximate(float4(fTime * 0.1 + fOffset, fGlobalTime * fTurbulence * 0.1 + fOffset, 0, 0));
    float p = osc.x * osc.y;
    return 1.0 - p * p * fTurbulence;
}

// Whole-tree sway: vertices above a quarter of the tree height move along
// the wind by (height above that)^exponent times an oscillation plus the
// trunk's adherence; bPreserveShape keeps each vertex's distance to the root.
float3 GlobalWind(float3 vPos, float3 vInstancePos, bool bPreserveShape, float3 vRotatedWindVector, float time)
{
    float length0 = bPreserveShape ? length(vPos) : 1.0;

#ifdef SPEEDTREE_Z_UP
    float height = vPos.z;
#else
    float height = vPos.y;
#endif
    float adjust = max(height - (1.0 / _ST_WindGlobal.z) * 0.25, 0.0) * _ST_WindGlobal.z;
    if (adjust != 0.0)
        adjust = pow(abs(adjust), _ST_WindGlobal.w);

    float4 osc = TrigApproximate(float4(vInstancePos.x + time, vInstancePos.y + time * 0.8, 0, 0));
    float moveAmount = _ST_WindGlobal.y * (osc.x + osc.y * osc.y);
    moveAmount += _ST_WindBranchAdherences.x / _ST_WindGlobal.z;
    moveAmount *= adjust;

#ifdef SPEEDTREE_Z_UP
    vPos.xy += vRotatedWindVector.xy * moveAmount;
#else
    vPos.xz += vRotatedWindVector.xz * moveAmount;
#endif

    if (bPreserveShape)
        vPos = normalize(vPos) * length0;
    return vPos;
}

// Shared start of the branch winds: the branch's packed direction scaled by
// its weight, a time offset per instance so trees do not sway in step, and
// the oscillation along that direction.
float3 FacetBranchOscillate(inout float3 vPos, float3 vInstancePos, float fWeight, float fOffset,
                            inout float fTime, float fDistance, float fTwitch, float fTwitchScale,
                            float fWhip, bool bWhip, bool bComplex, out float4 vOscillations,
                            float3 vRotatedWindVector)
{
    float3 windVector = UnpackNormalFromFloat(fOffset) * fWeight;
    fTime += vInstancePos.x + vInstancePos.y;
    float osc = Oscillate(vPos, fTime, fOffset, fWeight, fWhip, bWhip, false, bComplex, fTwitch, fTwitchScale, vOscillations, vRotatedWindVector);
    vPos += windVector * osc * fDistance;
    return windVector;
}

// The adherence scale of the directional winds: turbulence, plus whip.
float FacetBranchAdherenceScale(float fTime, float fOffset, float fTurbulence, float fWhip,
                                bool bWhip, bool bTurbulence, float4 vOscillations)
{
    float scale = bTurbulence ? Turbulence(fTime, fOffset, _ST_WindAnimation.x, fTurbulence) : 1.0;
    if (bWhip)
        scale += vOscillations.w * _ST_WindVector.w * fWhip;
    return scale;
}

// Branches oscillate about their rest position.
float3 SimpleBranchWind(float3 vPos, float3 vInstancePos, float fWeight, float fOffset, float fTime,
                        float fDistance, float fTwitch, float fTwitchScale, float fWhip,
                        bool bWhip, bool bRoll, bool bComplex, float3 vRotatedWindVector)
{
    float4 osc;
    FacetBranchOscillate(vPos, vInstancePos, fWeight, fOffset, fTime, fDistance, fTwitch, fTwitchScale,
                         fWhip, bWhip, bComplex, osc, vRotatedWindVector);
    return vPos;
}

// ... and also lean along the wind by their adherence.
float3 DirectionalBranchWind(float3 vPos, float3 vInstancePos, float fWeight, float fOffset, float fTime,
                             float fDistance, float fTurbulence, float fAdherence, float fTwitch,
                             float fTwitchScale, float fWhip, bool bWhip, bool bRoll, bool bComplex,
                             bool bTurbulence, float3 vRotatedWindVector)
{
    float4 osc;
    FacetBranchOscillate(vPos, vInstancePos, fWeight, fOffset, fTime, fDistance, fTwitch, fTwitchScale,
                         fWhip, bWhip, bComplex, osc, vRotatedWindVector);
    float scale = FacetBranchAdherenceScale(fTime, fOffset, fTurbulence, fWhip, bWhip, bTurbulence, osc);
    vPos += vRotatedWindVector * fAdherence * scale * fWeight;
    return vPos;
}

// Palm fronds: lean towards the wind's branch anchor point instead.
float3 DirectionalBranchWindFrondStyle(float3 vPos, float3 vInstancePos, float fWeight, float fOffset,
                                       float fTime, float fDistance, float fTurbulence, float fAdherence,
                                       float fTwitch, float fTwitchScale, float fWhip, bool bWhip,
                                       bool bRoll, bool bComplex, bool bTurbulence,
                                       float3 vRotatedWindVector, float3 vRotatedBranchAnchor)
{
    float4 osc;
    FacetBranchOscillate(vPos, vInstancePos, fWeight, fOffset, fTime, fDistance, fTwitch, fTwitchScale,
                         fWhip, bWhip, bComplex, osc, vRotatedWindVector);
    float scale = FacetBranchAdherenceScale(fTime, fOffset, fTurbulence, fWhip, bWhip, bTurbulence, osc);
    vPos += (vRotatedBranchAnchor - vPos) * fAdherence * scale * fWeight;
    return vPos;
}

// Branch wind for the better/best/palm qualities; vWindData.xy = (branch
// weight, packed branch direction) from the mesh.
float3 BranchWind(bool isPalmWind, float3 vPos, float3 vInstancePos, float4 vWindData,
                  float3 vRotatedWindVector, float3 vRotatedBranchAnchor)
{
    if (isPalmWind)
        return DirectionalBranchWindFrondStyle(vPos, vInstancePos, vWindData.x, vWindData.y,
            _ST_WindBranch.x, _ST_WindBranch.y, _ST_WindTurbulences.x, _ST_WindBranchAdherences.y,
            _ST_WindBranchTwitch.x, _ST_WindBranchTwitch.y, _ST_WindBranchWhip.x,
            true, false, true, true, vRotatedWindVector, vRotatedBranchAnchor);
    return SimpleBranchWind(vPos, vInstancePos, vWindData.x, vWindData.y,
        _ST_WindBranch.x, _ST_WindBranch.y, _ST_WindBranchTwitch.x, _ST_WindBranchTwitch.y,
        _ST_WindBranchWhip.x, false, false, true, vRotatedWindVector);
}

// Leaf ripple: a wave along vDirection (the normal) or a packed direction.
float3 LeafRipple(float3 vPos, inout float3 vDirection, float fScale, float fPackedRippleDir,
                  float fTime, float fAmount, bool bDirectional, float fTrigOffset)
{
    float move = fAmount * TrigApproximate(float4(fTime + fTrigOffset, 0, 0, 0)).x;
    float3 dir = bDirectional ? vDirection : UnpackNormalFromFloat(fPackedRippleDir);
    return vPos + dir * move * fScale;
}

// Leaf tumble: the leaf card turns about its anchor, twisting about its
// growth direction and flipping about the axis that turns it into the wind
// (by its adherence, plus oscillation and twitch). The normal (vDirection)
// turns with it.
float3 LeafTumble(float3 vPos, inout float3 vDirection, float fScale, float3 vAnchor, float3 vGrowthDir,
                  float fTrigOffset, float fTime, float fFlip, float fTwist, float fAdherence,
                  float3 vTwitch, float4 vRoll, bool bTwitch, bool bRoll, float3 vRotatedWindVector)
{
    float3 fracs = frac((vAnchor + fTrigOffset) * 30.3);
    float offset = fracs.x + fracs.y + fracs.z;
    float4 osc = TrigApproximate(float4(fTime + offset, fTime * 0.75 - offset, fTime * 0.01 + offset, fTime + offset));

    float3 fromAnchor = vPos - vAnchor;
    float len = length(fromAnchor);

    float3x3 tumble = RotationMatrix(vGrowthDir, fScale * fTwist * (osc.x + osc.y * osc.y));

    float windDot = clamp(dot(vRotatedWindVector, vGrowthDir), -1.0, 1.0);
    float3 axis = wind_cross(vGrowthDir, vRotatedWindVector);
#ifdef SPEEDTREE_Z_UP
    axis.z += windDot;
#else
    axis.y += windDot;
#endif
    axis = normalize(axis);
    float angle = acos(windDot);

    float twitch = bTwitch ? Twitch(vAnchor, vTwitch.x, vTwitch.y, vTwitch.z + offset) : 0.0;
    float flip = osc.y - osc.x * osc.x;
    tumble = mul_float3x3_float3x3(tumble, RotationMatrix(axis, fScale * (angle * fAdherence + flip * fFlip + twitch)));

    vDirection = mul_float3x3_float3(tumble, vDirection);
    fromAnchor = normalize(mul_float3x3_float3(tumble, fromAnchor)) * len;
    return fromAnchor + vAnchor;
}

// Leaf wind: ripple always, tumble/twitch at the best quality; leaf group 2
// (bLeaf2) reads the Leaf2 uniforms.
float3 LeafWind(bool isBestWind, bool bLeaf2, float3 vPos, inout float3 vDirection, float fScale,
                float3 vAnchor, float fPackedGrowthDir, float fPackedRippleDir, float fRippleTrigOffset,
                float3 vRotatedWindVector)
{
    float4 ripple = bLeaf2 ? _ST_WindLeaf2Ripple : _ST_WindLeaf1Ripple;
    vPos = LeafRipple(vPos, vDirection, fScale, fPackedRippleDir, ripple.x, ripple.y, false, fRippleTrigOffset);
    if (isBestWind)
    {
        float4 tumble = bLeaf2 ? _ST_WindLeaf2Tumble : _ST_WindLeaf1Tumble;
        float3 twitch = bLeaf2 ? _ST_WindLeaf2Twitch.xyz : _ST_WindLeaf1Twitch.xyz;
        vPos = LeafTumble(vPos, vDirection, fScale, vAnchor, UnpackNormalFromFloat(fPackedGrowthDir),
                          fPackedGrowthDir, tumble.x, tumble.y, tumble.z, tumble.w, twitch, 0.0f,
                          true, true, vRotatedWindVector);
    }
    return vPos;
}

// With WIND_EFFECT_FROND_RIPPLE_ADJUST_LIGHTING the rippled frond's normal
// is rebuilt from its bent tangent.
#ifdef WIND_EFFECT_FROND_RIPPLE_ADJUST_LIGHTING
    #define FACET_FROND_FRAME_PARAMS , float3 vBinormal, float3 vTangent
    #define FACET_FROND_FRAME_ARGS , vBinormal, vTangent
    void FacetFrondAdjustNormal(float3 offset, inout float3 vDirection, float3 vBinormal, float3 vTangent)
    {
        vTangent = normalize(vTangent + offset * _ST_WindFrondRipple.w);
        float3 n = normalize(wind_cross(vBinormal, vTangent));
        vDirection = dot(n, vDirection) < 0.0 ? -n : n;
    }
#else
    #define FACET_FROND_FRAME_PARAMS
    #define FACET_FROND_FRAME_ARGS
#endif

// One-sided fronds ripple along their normal, a wave running down the frond
// (fV) with the two halves (fU < 0.5) out of phase.
float3 RippleFrondOneSided(float3 vPos, inout float3 vDirection, float fU, float fV, float fRippleScale
                           FACET_FROND_FRAME_PARAMS)
{
    float phase = (_ST_WindFrondRipple.x + fV) * _ST_WindFrondRipple.z + (fU < 0.5 ? 0.75 : 0.0);
    float3 offset = fRippleScale * TrigApproximate(float4(phase, 0, 0, 0)).x * _ST_WindFrondRipple.y * vDirection;
#ifdef WIND_EFFECT_FROND_RIPPLE_ADJUST_LIGHTING
    FacetFrondAdjustNormal(offset, vDirection, vBinormal, vTangent);
#endif
    return vPos + offset;
}

// Two-sided fronds ripple along a packed direction.
float3 RippleFrondTwoSided(float3 vPos, inout float3 vDirection, float fU, float fLengthPercent,
                           float fPackedRippleDir, float fRippleScale FACET_FROND_FRAME_PARAMS)
{
    float wave = TrigApproximate(float4(_ST_WindFrondRipple.x * fLengthPercent * _ST_WindFrondRipple.z, 0, 0, 0)).x;
    float3 offset = fRippleScale * wave * _ST_WindFrondRipple.y * UnpackNormalFromFloat(fPackedRippleDir);
#ifdef WIND_EFFECT_FROND_RIPPLE_ADJUST_LIGHTING
    FacetFrondAdjustNormal(offset, vDirection, vBinormal, vTangent);
#endif
    return vPos + offset;
}

// Palm frond ripple (the one-sided form, as SpeedTree's runtime uses).
float3 RippleFrond(float3 vPos, inout float3 vDirection, float fU, float fV, float fPackedRippleDir,
                   float fRippleScale, float fLenghtPercent FACET_FROND_FRAME_PARAMS)
{
    return RippleFrondOneSided(vPos, vDirection, fU, fV, fRippleScale FACET_FROND_FRAME_ARGS);
}

#endif // SPEEDTREE_8_WIND

#if SPEEDTREE_9_WIND
///////////////////////////////////////////////////////////////////////////////
// SpeedTree 9 wind

#include "SpeedTreeShaderLibrary.cginc"

struct WindBranchState
{
    float3 m_vNoisePosTurbulence;
    float m_fIndependence;
    float m_fBend;
    float m_fOscillation;
    float m_fTurbulence;
    float m_fFlexibility;
};
struct WindRippleState
{
    float3 m_vNoisePosTurbulence;
    float m_fIndependence;
    float m_fPlanar;
    float m_fDirectional;
    float m_fFlexibility;
    float m_fShimmer;
};
struct CBufferSpeedTree9
{
    float3 m_vWindDirection;
    float m_fWindStrength;
    float3 m_vTreeExtents;
    float m_fSharedHeightStart;
    float m_fBranch1StretchLimit;
    float m_fBranch2StretchLimit;
    float m_fWindIndependence;
    float m_fImportScaling;
    WindBranchState m_sShared;
    WindBranchState m_sBranch1;
    WindBranchState m_sBranch2;
    WindRippleState m_sRipple;
};

// Current values and the previous frame's (History, for motion vectors).
float4 _ST_TreeExtents_SharedHeightStart;
float4 _ST_BranchStretchLimits;     // x, y = branch 1, 2 stretch limits, z = wind independence, w = import scaling
float4 _ST_Shared_NoisePosTurbulence_Independence;
float4 _ST_Shared_Bend_Oscillation_Turbulence_Flexibility;
float4 _ST_Branch1_NoisePosTurbulence_Independence;
float4 _ST_Branch1_Bend_Oscillation_Turbulence_Flexibility;
float4 _ST_Branch2_NoisePosTurbulence_Independence;
float4 _ST_Branch2_Bend_Oscillation_Turbulence_Flexibility;
float4 _ST_Ripple_NoisePosTurbulence_Independence;
float4 _ST_Ripple_Planar_Directional_Flexibility_Shimmer;
float4 _ST_HistoryWindVector;
float4 _ST_HistoryTreeExtents_SharedHeightStart;
float4 _ST_HistoryBranchStretchLimits;
float4 _ST_HistoryShared_NoisePosTurbulence_Independence;
float4 _ST_HistoryShared_Bend_Oscillation_Turbulence_Flexibility;
float4 _ST_HistoryBranch1_NoisePosTurbulence_Independence;
float4 _ST_HistoryBranch1_Bend_Oscillation_Turbulence_Flexibility;
float4 _ST_HistoryBranch2_NoisePosTurbulence_Independence;
float4 _ST_HistoryBranch2_Bend_Oscillation_Turbulence_Flexibility;
float4 _ST_HistoryRipple_NoisePosTurbulence_Independence;
float4 _ST_HistoryRipple_Planar_Directional_Flexibility_Shimmer;

WindBranchState FacetWindBranchState(float4 noiseIndependence, float4 bendOscTurbFlex)
{
    WindBranchState s;
    s.m_vNoisePosTurbulence = noiseIndependence.xyz;
    s.m_fIndependence = noiseIndependence.w;
    s.m_fBend = bendOscTurbFlex.x;
    s.m_fOscillation = bendOscTurbFlex.y;
    s.m_fTurbulence = bendOscTurbFlex.z;
    s.m_fFlexibility = bendOscTurbFlex.w;
    return s;
}

// Gathers the wind uniforms (bHistory: the previous frame's) into one
// struct; the wind direction is turned into the object's space.
CBufferSpeedTree9 ReadCBuffer(bool bHistory)
{
    CBufferSpeedTree9 cb;
    float4 wind = bHistory ? _ST_HistoryWindVector : _ST_WindVector;
    float4 extents = bHistory ? _ST_HistoryTreeExtents_SharedHeightStart : _ST_TreeExtents_SharedHeightStart;
    float4 limits = bHistory ? _ST_HistoryBranchStretchLimits : _ST_BranchStretchLimits;
    cb.m_vWindDirection = TransformWindVectorFromWorldToLocalSpace(wind.xyz);
    cb.m_fWindStrength = wind.w;
    cb.m_vTreeExtents = extents.xyz;
    cb.m_fSharedHeightStart = extents.w;
    cb.m_fBranch1StretchLimit = limits.x;
    cb.m_fBranch2StretchLimit = limits.y;
    cb.m_fWindIndependence = limits.z;
    cb.m_fImportScaling = limits.w;
    if (bHistory)
    {
        cb.m_sShared = FacetWindBranchState(_ST_HistoryShared_NoisePosTurbulence_Independence, _ST_HistoryShared_Bend_Oscillation_Turbulence_Flexibility);
        cb.m_sBranch1 = FacetWindBranchState(_ST_HistoryBranch1_NoisePosTurbulence_Independence, _ST_HistoryBranch1_Bend_Oscillation_Turbulence_Flexibility);
        cb.m_sBranch2 = FacetWindBranchState(_ST_HistoryBranch2_NoisePosTurbulence_Independence, _ST_HistoryBranch2_Bend_Oscillation_Turbulence_Flexibility);
    }
    else
    {
        cb.m_sShared = FacetWindBranchState(_ST_Shared_NoisePosTurbulence_Independence, _ST_Shared_Bend_Oscillation_Turbulence_Flexibility);
        cb.m_sBranch1 = FacetWindBranchState(_ST_Branch1_NoisePosTurbulence_Independence, _ST_Branch1_Bend_Oscillation_Turbulence_Flexibility);
        cb.m_sBranch2 = FacetWindBranchState(_ST_Branch2_NoisePosTurbulence_Independence, _ST_Branch2_Bend_Oscillation_Turbulence_Flexibility);
    }
    float4 rippleNoise = bHistory ? _ST_HistoryRipple_NoisePosTurbulence_Independence : _ST_Ripple_NoisePosTurbulence_Independence;
    float4 ripple = bHistory ? _ST_HistoryRipple_Planar_Directional_Flexibility_Shimmer : _ST_Ripple_Planar_Directional_Flexibility_Shimmer;
    cb.m_sRipple.m_vNoisePosTurbulence = rippleNoise.xyz;
    cb.m_sRipple.m_fIndependence = rippleNoise.w;
    cb.m_sRipple.m_fPlanar = ripple.x;
    cb.m_sRipple.m_fDirectional = ripple.y;
    cb.m_sRipple.m_fFlexibility = ripple.z;
    cb.m_sRipple.m_fShimmer = ripple.w;
    return cb;
}

// Hash and value noise (smooth 2D noise from hashed lattice corners).
float NoiseHash(float n) { return frac(sin(n) * 1e4); }
float NoiseHash(float2 p) { return frac(1e4 * sin(17.0f * p.x + p.y * 0.1f) * (0.1f + abs(sin(p.y * 13.0f + p.x)))); }
float QNoise(float2 x)
{
    float2 i = floor(x), f = frac(x);
    float a = NoiseHash(i), b = NoiseHash(i + float2(1, 0));
    float c = NoiseHash(i + float2(0, 1)), d = NoiseHash(i + float2(1, 1));
    float2 u = f * f * (3.0 - 2.0 * f);
    return lerp(a, b, u.x) + (c - a) * u.y * (1.0f - u.x) + (d - b) * u.x * u.y;
}

// Three noise values about 0 (x, y and their sum) at the xz of a noise
// position. (Unity can read a noise texture instead; facet always computes.)
float4 RuntimeSdkNoise2DFlat(float3 vNoisePos3d)
{
    float2 p = vNoisePos3d.xz * 20.0f;
    float nx = QNoise(p);
    float ny = QNoise(p.yx * 0.5f);
    return float4(nx, ny, nx + ny, 0.0f) - 0.5f;
}

float  WindUtil_Square(float  fValue) { return fValue * fValue; }
float2 WindUtil_Square(float2 fValue) { return fValue * fValue; }
float3 WindUtil_Square(float3 fValue) { return fValue * fValue; }
float4 WindUtil_Square(float4 fValue) { return fValue * fValue; }

// A unit vector packed into one float as three base-100 digit pairs.
float3 WindUtil_UnpackNormalizedFloat(float fValue)
{
    float3 v = frac(float3(fValue * 0.01f, fValue, fValue * 100.0f));
    return normalize((v - 0.5f) * 2.0f);
}

// Leaf ripple: an offset (the caller adds it) along the wind and the up axis
// from noise, scaled by the vertex's ripple weight.
float3 RippleWindMotion(float3 vUp, float3 vWindDirection, float3 vVertexPositionIn, float3 vGlobalNoisePosition,
                        float fRippleWeight, float3 vRippleNoisePosTurbulence, float fRippleIndependence,
                        float fRippleFlexibility, float fRippleDirectional, float fRipplePlanar,
                        float fTreeHeight, float fImportScaling)
{
    float3 noisePos = vGlobalNoisePosition + vRippleNoisePosTurbulence
                    + (vVertexPositionIn / fImportScaling) * fRippleIndependence
                    + vWindDirection * fRippleFlexibility * fRippleWeight;
    float2 noise = RuntimeSdkNoise2DFlat(noisePos).xy;
    noise.x += 0.25f;   // bias along the wind
    return (vWindDirection * noise.x * fRippleDirectional + vUp * (noise.y * fRipplePlanar)) * fRippleWeight;
}

// Branch bend: the vertex swings about an anchor that lies fBranchWeight *
// stretch limit back along the branch's packed direction, bent towards the
// wind (lifted when the branch points along it) with noise-driven
// oscillation and turbulence; the distance to the anchor is kept.
float3 BranchWindPosition(float3 vUp, float3 vWindDirection, float3 vVertexPositionIn, float3 vGlobalNoisePosition,
                          float fPackedBranchDir, float fPackedBranchNoiseOffset, float fBranchWeight,
                          float fBranchStretchLimit, float3 vBranchNoisePosTurbulence, float fBranchIndependence,
                          float fBranchTurbulence, float fBranchOscillation, float fBranchBend,
                          float fBranchFlexibility, float fTreeHeight, float fImportScaling)
{
    float len = fBranchWeight * fBranchStretchLimit;
    if (len <= 0.0f)
        return vVertexPositionIn;

    // packed Z-up by the modeller: rotate -90 degrees about x into Y-up
    float3 branchDir = WindUtil_UnpackNormalizedFloat(fPackedBranchDir);
    float3 noiseOffset = WindUtil_UnpackNormalizedFloat(fPackedBranchNoiseOffset);
    branchDir = float3(branchDir.x, -branchDir.z, branchDir.y);
    noiseOffset = float3(noiseOffset.x, -noiseOffset.z, noiseOffset.y);

    float3 anchor = vVertexPositionIn - branchDir * len;
    float3 fromAnchor = vVertexPositionIn - anchor;

    float3 wind = normalize(vWindDirection + vUp * WindUtil_Square(dot(branchDir, vWindDirection)));
    // the modeller divides independence by the tree height, the importer scales the height
    fBranchIndependence *= fTreeHeight / fImportScaling;

    float3 noisePos = vGlobalNoisePosition + vBranchNoisePosTurbulence + noiseOffset * fBranchIndependence
                    + wind * (fBranchFlexibility * fBranchWeight);
    float4 noise = RuntimeSdkNoise2DFlat(noisePos);
    noise.xy *= float2(0.65, 0.5);   // calmer flexible branches

    float3 motion = (wind * noise.x + vUp * fBranchTurbulence * noise.y) * fBranchOscillation
                  + wind * (fBranchBend * (1.0f - noise.z));
    motion *= fBranchWeight;
    return normalize(fromAnchor + motion) * len + anchor;
}

// Whole-tree bend: weight grows with the square of the height above the
// shared start height; the vertex's distance to the root is kept. (As in
// Unity's shader, the noise position is the global position plus the shared
// turbulence offset only: the flexibility term does not reach it.)
float3 SharedWindPosition(float3 vUp, float3 vWindDirection, float3 vVertexPositionIn, float3 vGlobalNoisePosition,
                          float fTreeHeight, float fSharedHeightStart, float3 vSharedNoisePosTurbulence,
                          float fSharedTurbulence, float fSharedOscillation, float fSharedBend,
                          float fSharedFlexibility, float fImportScaling)
{
    float lenSq = dot(vVertexPositionIn, vVertexPositionIn);
    if (lenSq == 0.0f)
        return vVertexPositionIn;

    float weight = WindUtil_Square(max(vVertexPositionIn.y - fTreeHeight * fSharedHeightStart, 0.0f) / fTreeHeight);
    float4 noise = RuntimeSdkNoise2DFlat(vGlobalNoisePosition + vSharedNoisePosTurbulence);
    float3 sideways = cross(vWindDirection, vUp) * fSharedTurbulence;
    float3 motion = (vWindDirection * noise.x + sideways * noise.y) * fSharedOscillation
                  + vWindDirection * (fSharedBend * (1.0f - noise.z));
    return normalize(vVertexPositionIn + motion * weight) * sqrt(lenSq);
}

#endif // SPEEDTREE_9_WIND

#endif // SPEEDTREE_WIND_INCLUDED
