// Compile-time switches of the Standard shader library, each overridable by
// defining it before the first include.
#ifndef UNITY_STANDARD_CONFIG_INCLUDED
#define UNITY_STANDARD_CONFIG_INCLUDED

// Mips of the reflection probe from mirror to fully rough (roughness -> mip).
#ifndef UNITY_SPECCUBE_LOD_STEPS
#define UNITY_SPECCUBE_LOD_STEPS (6)
#endif

// BRDF1/BRDF2 microfacet distribution: 1 = GGX, 0 = normalized Blinn-Phong.
#ifndef UNITY_BRDF_GGX
#define UNITY_BRDF_GGX 1
#endif

// Diffuse scaled by 1 - max(specular) (energy conservation).
#ifndef UNITY_CONSERVE_ENERGY
#define UNITY_CONSERVE_ENERGY 1
#endif
#ifndef UNITY_CONSERVE_ENERGY_MONOCHROME
#define UNITY_CONSERVE_ENERGY_MONOCHROME 1
#endif

// Flip a back-facing normal instead of abs(N.V) in BRDF1: off, as in Unity.
#ifndef UNITY_HANDLE_CORRECTLY_NEGATIVE_NDOTV
#define UNITY_HANDLE_CORRECTLY_NEGATIVE_NDOTV 0
#endif

// Reflection-probe box projection and blending, on as in Unity's tier-3
// desktop settings: box projection follows each probe's ProbePosition.w,
// blending unity_SpecCube0_BoxMin.w (1 when an object has one probe).
#ifndef UNITY_SPECCUBE_BOX_PROJECTION
#define UNITY_SPECCUBE_BOX_PROJECTION 1
#endif
#ifndef UNITY_SPECCUBE_BLENDING
#define UNITY_SPECCUBE_BLENDING 1
#endif

// Per-pixel world position in the fragment (needed by box projection and
// per-pixel light attenuation).
#ifndef UNITY_REQUIRE_FRAG_WORLDPOS
#define UNITY_REQUIRE_FRAG_WORLDPOS 1
#endif
#ifndef UNITY_PACK_WORLDPOS_WITH_TANGENT
#define UNITY_PACK_WORLDPOS_WITH_TANGENT 0
#endif

// SH evaluated per pixel (1) or per vertex (0).
#ifndef UNITY_SAMPLE_FULL_SH_PER_PIXEL
#define UNITY_SAMPLE_FULL_SH_PER_PIXEL 1
#endif

// Specular highlights / glossy reflections, from the material toggles.
#if defined(_SPECULARHIGHLIGHTS_OFF)
#define SPECULAR_HIGHLIGHTS 0
#else
#define SPECULAR_HIGHLIGHTS 1
#endif
#if defined(_GLOSSYREFLECTIONS_OFF)
#define GLOSSY_REFLECTIONS 0
#else
#define GLOSSY_REFLECTIONS 1
#endif

// The simplified forward path (UnityStandardCoreForwardSimple.cginc) where
// a platform asks for it.
#if defined(UNITY_NO_FULL_STANDARD_SHADER) && !defined(UNITY_STANDARD_SIMPLE)
#define UNITY_STANDARD_SIMPLE 1
#endif

// Tangent-to-world basis in the interpolators when a normal map or
// parallax map needs it.
#if defined(_NORMALMAP) || defined(_PARALLAXMAP) || defined(DIRLIGHTMAP_COMBINED)
#define _TANGENT_TO_WORLD 1
#endif

// The second detail/UV channel: _DETAIL_MULX2 and friends.
#if defined(_DETAIL_MULX2) || defined(_DETAIL_MUL) || defined(_DETAIL_ADD) || defined(_DETAIL_LERP)
#define _DETAIL 1
#endif

#endif // UNITY_STANDARD_CONFIG_INCLUDED
