// TextCore's screen-space signed-distance-field text (TextCore-SDF-SSD):
// VertShader/PixShader over the properties of TextCore_Properties.cginc.
// The face covers the atlas distance above the dilated threshold with an
// antialiasing ramp one screen pixel wide; OUTLINE_ON adds an outline band,
// UNDERLAY_ON / UNDERLAY_INNER a drop shadow outside / inside the glyph. The
// result (premultiplied alpha) is masked by the GUI clip texture.
#ifndef FACET_TEXTCORE_SDF_SSD_INCLUDED
#define FACET_TEXTCORE_SDF_SSD_INCLUDED

#include "UnityCG.cginc"
#include "FacetColor.hlsl"
#include "TextCore_Properties.cginc"

struct vertex_t
{
    float4 position : POSITION;
    float3 normal : NORMAL;
    float4 color : COLOR;
    float4 texcoord0 : TEXCOORD0;
    float2 texcoord1 : TEXCOORD1;   // y <= 0: bold
};

struct pixel_t
{
    float4 position : SV_POSITION;
    float4 faceColor : COLOR;
    float4 outlineColor : COLOR1;
    float2 texcoord0 : TEXCOORD0;
    float4 param : TEXCOORD1;       // x: distance threshold, y: distance scale, z: outline half width
    float2 clipUV : TEXCOORD2;
#if (UNDERLAY_ON || UNDERLAY_INNER)
    float4 texcoord2 : TEXCOORD3;   // xy: underlay uv, z: vertex alpha
    float4 underlayColor : COLOR2;
#endif
};

sampler2D _GUIClipTexture;
uniform float4x4 unity_GUIClipTextureMatrix;
float4 _MainTex_TexelSize;

float4 SRGBToLinear(float4 rgba) { return float4(FacetSRGBToLinear(rgba.rgb), rgba.a); }

pixel_t VertShader(vertex_t input)
{
    float4 position = input.position;
    position.xy += float2(_VertexOffsetX, _VertexOffsetY);

    float isBold = step(input.texcoord1.y, 0.0);
    float weight = (lerp(_WeightNormal, _WeightBold, isBold) * 0.25 + _FaceDilate) * _ScaleRatioA * 0.5;

    float4 color = input.color;
#if (FORCE_LINEAR && !UNITY_COLORSPACE_GAMMA)
    color = SRGBToLinear(color);
#endif
#if (UNDERLAY_ON || UNDERLAY_INNER)
    float opacity = 1.0;    // the vertex alpha fades the whole stack at the end instead
#else
    float opacity = color.a;
#endif
    float4 face = float4(color.rgb, opacity) * _FaceColor;
    face.rgb *= face.a;
    float4 outline = _OutlineColor;
    outline.a *= opacity;
    outline.rgb *= outline.a;

    pixel_t o;
    o.position = UnityObjectToClipPos(position);
    o.faceColor = face;
    o.outlineColor = outline;
    o.texcoord0 = input.texcoord0.xy;
    o.param = float4(0.5 - weight, 1.3333 * _GradientScale * (_Sharpness + 1.0) / _MainTex_TexelSize.w,
                     _OutlineWidth * _ScaleRatioA * 0.5, 0.0);
    float3 viewPos = UnityObjectToViewPos(input.position.xyz);
    o.clipUV = mul(unity_GUIClipTextureMatrix, float4(viewPos.xy, 0.0, 1.0)).xy;
#if (UNDERLAY_ON || UNDERLAY_INNER)
    float2 shift = -float2(_UnderlayOffsetX, _UnderlayOffsetY) * _ScaleRatioC * _GradientScale / _MainTex_TexelSize.zw;
    o.texcoord2 = float4(input.texcoord0.xy + shift, input.color.a, 0.0);
    o.underlayColor = float4(_UnderlayColor.rgb * _UnderlayColor.a, _UnderlayColor.a);
#endif
    return o;
}

float4 PixShader(pixel_t input) : SV_Target
{
    float2 uv = input.texcoord0.xy;
    float dist = tex2D(_MainTex, uv).a;
    // Distance units per screen pixel, from the atlas's derivative.
    float pixelSize = abs(ddx(uv.y)) + abs(ddy(uv.y));
    float sdfScale = input.param.y / pixelSize;
#if (UNDERLAY_ON || UNDERLAY_INNER)
    float underlayScale = sdfScale / (1.0 + _UnderlaySoftness * _ScaleRatioC * sdfScale);
    float underlayBias = input.param.x * underlayScale - 0.5 - _UnderlayDilate * _ScaleRatioC * 0.5 * underlayScale;
#endif
    sdfScale /= 1.0 + _OutlineSoftness * _ScaleRatioA * sdfScale;

    float4 c = input.faceColor * saturate((dist - input.param.x) * sdfScale + 0.5);
#ifdef OUTLINE_ON
    float4 rim = lerp(input.faceColor, input.outlineColor, sqrt(min(1.0, input.param.z * sdfScale * 2.0)));
    c = lerp(rim, input.faceColor, saturate((dist - input.param.x - input.param.z) * sdfScale + 0.5));
    c *= saturate((dist - input.param.x + input.param.z) * sdfScale + 0.5);
#endif
    float4 shadowColor = float4(_UnderlayColor.rgb * _UnderlayColor.a, _UnderlayColor.a);
#if UNDERLAY_ON
    float behind = tex2D(_MainTex, input.texcoord2.xy).a * underlayScale;
    c += shadowColor * saturate(behind - underlayBias) * (1.0 - c.a);
#endif
#if UNDERLAY_INNER
    float inside = saturate(dist * sdfScale - (input.param.x * sdfScale - 0.5) - input.param.z);
    float inner = tex2D(_MainTex, input.texcoord2.xy).a * underlayScale;
    c += shadowColor * (1.0 - saturate(inner - underlayBias)) * inside * (1.0 - c.a);
#endif
#if (UNDERLAY_ON || UNDERLAY_INNER)
    c *= input.texcoord2.z;
#endif
    return c * tex2D(_GUIClipTexture, input.clipUV).a;
}

#endif // FACET_TEXTCORE_SDF_SSD_INCLUDED
