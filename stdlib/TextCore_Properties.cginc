// The material properties of TextCore's signed-distance-field text shaders
// (TextCore-SDF, TextCore-SDF-SSD): the font atlas, face, outline, bevel,
// lighting, underlay and glow settings, and the values TextCore's C# side
// sets (weights, scale ratios, masking). Declarations only.
// TextCoreProperties.cginc is the older name of this file.
#ifndef FACET_TEXTCORE_PROPERTIES_INCLUDED
#define FACET_TEXTCORE_PROPERTIES_INCLUDED

#include "HLSLSupport.cginc"

// The font atlas: distance in alpha.
uniform sampler2D _MainTex;
uniform float _TextureWidth, _TextureHeight;
uniform float _GradientScale;     // the atlas's distance range in texels
uniform float _ScaleX, _ScaleY;
uniform float _PerspectiveFilter;
uniform float _Sharpness;

// Face and outline.
uniform sampler2D _FaceTex;
uniform float _FaceUVSpeedX, _FaceUVSpeedY;
uniform fixed4 _FaceColor;
uniform float _FaceDilate;
uniform float _OutlineSoftness;
uniform sampler2D _OutlineTex;
uniform float _OutlineUVSpeedX, _OutlineUVSpeedY;
uniform fixed4 _OutlineColor;
uniform float _OutlineWidth;

// Bevel and its normal map.
uniform float _Bevel, _BevelOffset, _BevelWidth, _BevelClamp, _BevelRoundness;
uniform sampler2D _BumpMap;
uniform float _BumpOutline, _BumpFace;

// Environment reflection and the light.
uniform samplerCUBE _Cube;
uniform fixed4 _ReflectFaceColor, _ReflectOutlineColor;
uniform float3 _EnvMatrixRotation;
uniform float4x4 _EnvMatrix;
uniform fixed4 _SpecularColor;
uniform float _LightAngle, _SpecularPower, _Reflectivity, _Diffuse, _Ambient;

// Underlay (drop shadow) and glow.
uniform fixed4 _UnderlayColor;
uniform float _UnderlayOffsetX, _UnderlayOffsetY, _UnderlayDilate, _UnderlaySoftness;
uniform fixed4 _GlowColor;
uniform float _GlowOffset, _GlowOuter, _GlowInner, _GlowPower;

// Set by TextCore: style weights, the scale ratios of the dilations, vertex
// offset, and masking (clip rectangle as (xMin, yMin, xMax, yMax)).
uniform float _ShaderFlags;
uniform float _WeightNormal, _WeightBold;
uniform float _ScaleRatioA, _ScaleRatioB, _ScaleRatioC;
uniform float _VertexOffsetX, _VertexOffsetY;
uniform float _MaskID;
uniform sampler2D _MaskTex;
uniform float4 _MaskCoord;
uniform float4 _ClipRect;
uniform float _MaskSoftnessX, _MaskSoftnessY;

#endif // FACET_TEXTCORE_PROPERTIES_INCLUDED
