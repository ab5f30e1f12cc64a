// Helpers of the UI (uGUI) shaders: rectangle clipping (RectMask2D), the
// ETC1 split-alpha diffuse colour, and a gamma-to-linear conversion for
// vertex colours.
#ifndef UNITY_UI_INCLUDED
#define UNITY_UI_INCLUDED

#include "UnityCG.cginc"

// 1 inside the rectangle clipRect = (xMin, yMin, xMax, yMax), edges included; else 0.
inline float UnityGet2DClipping(in float2 position, in float4 clipRect)
{
    float2 inside = step(clipRect.xy, position.xy) * step(position.xy, clipRect.zw);
    return inside.x * inside.y;
}

// Colour from the main texture and alpha from the red channel of a separate
// alpha texture, each offset by textureSampleAdd.
inline fixed4 UnityGetUIDiffuseColor(in float2 position, in sampler2D mainTexture, in sampler2D alphaTexture,
                                     fixed4 textureSampleAdd)
{
    float3 rgb = tex2D(mainTexture, position).rgb + textureSampleAdd.rgb;
    float alpha = tex2D(alphaTexture, position).r + textureSampleAdd.a;
    return fixed4(rgb, alpha);
}

// sRGB-encoded colour to linear. Unity uses a cheap piecewise fit; facet
// takes the exact curve (FacetSrgbToLinear), within its 0.5/255 tolerance.
half3 UIGammaToLinear(half3 value) { return FacetSrgbToLinear(value); }

#endif // UNITY_UI_INCLUDED
