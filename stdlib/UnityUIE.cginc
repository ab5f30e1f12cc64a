// UI Toolkit's (UIElements) immediate renderer, Unity 2019.4: the vertex
// layout the renderer writes (appdata_t), the per-element data it keeps in
// the shader-info texture (3 texels of transform rows per element, a clip
// rectangle and an opacity texel; constant arrays instead below shader model
// 3.0), and the standard vert/frag that draw solid, atlas, text (bitmap or
// SDF with UIE_SDF_TEXT), custom-texture and SVG-gradient geometry. A shader
// that defines UIE_CUSTOM_SHADER writes its own vert/frag over
// uie_std_vert/uie_std_frag.
#ifndef UNITY_UIE_INCLUDED
#define UNITY_UIE_INCLUDED

// Configuration; a shader may preset each of these before the include.
// Colour space: gamma projects interpolate and write fixed colours.
#if !defined(UIE_COLORSPACE_GAMMA) && defined(UNITY_COLORSPACE_GAMMA)
#define UIE_COLORSPACE_GAMMA 1
#elif !defined(UIE_COLORSPACE_GAMMA)
#define UIE_COLORSPACE_GAMMA 0
#endif
#if !defined(UIE_V2F_COLOR_T) && UIE_COLORSPACE_GAMMA
#define UIE_V2F_COLOR_T fixed4
#elif !defined(UIE_V2F_COLOR_T)
#define UIE_V2F_COLOR_T half4
#endif
#if !defined(UIE_FRAG_T) && UIE_COLORSPACE_GAMMA
#define UIE_FRAG_T fixed4
#elif !defined(UIE_FRAG_T)
#define UIE_FRAG_T half4
#endif
// Below shader model 3.0 the per-element data lives in constant arrays of
// UIE_SKIN_ELEMS_COUNT_MAX_CONSTANTS slots, and one bilinear sampler serves
// the atlas (point and bilinear samplers, chosen per vertex, otherwise).
#if SHADER_TARGET < 30
#define UIE_SHADER_INFO_IN_VS 0
#else
#define UIE_SHADER_INFO_IN_VS 1
#endif
#if !defined(UIE_SIMPLE_ATLAS) && SHADER_TARGET < 35
#define UIE_SIMPLE_ATLAS 1
#elif !defined(UIE_SIMPLE_ATLAS)
#define UIE_SIMPLE_ATLAS 0
#endif
#ifndef UIE_SKIN_ELEMS_COUNT_MAX_CONSTANTS
#define UIE_SKIN_ELEMS_COUNT_MAX_CONSTANTS 20
#endif

#include "UnityCG.cginc"

// The per-element data: a texture of shader-info texels, or (below shader
// model 3.0) constant arrays of transform rows and clip rectangles.
sampler2D _ShaderInfoTex;
float4 _ShaderInfoTex_TexelSize;
#if !UIE_SHADER_INFO_IN_VS
CBUFFER_START(UIClipRects)
float4 _ClipRects[UIE_SKIN_ELEMS_COUNT_MAX_CONSTANTS];   // one rectangle per element
CBUFFER_END
CBUFFER_START(UITransforms)
float4 _Transforms[UIE_SKIN_ELEMS_COUNT_MAX_CONSTANTS * 3];   // three rows per element
CBUFFER_END
#endif
float4 _PixelClipRect;       // framebuffer pixels: (xMin, yMin, xMax, yMax)
float4 _1PixelClipInvView;   // xy: one pixel in clip space; zw: one view unit in pixels

// What the geometry samples: the atlas, the font, a custom texture and the
// SVG gradient settings.
#if UIE_SIMPLE_ATLAS
sampler2D _MainTex;
#else
Texture2D _MainTex;
#endif
SamplerState uie_point_clamp_sampler;
SamplerState uie_linear_clamp_sampler;
float4 _MainTex_TexelSize;
float4 _MainTex_ST;
sampler2D _FontTex;
float4 _FontTex_ST;
sampler2D _CustomTex;
float4 _CustomTex_TexelSize;
float4 _CustomTex_ST;
sampler2D _GradientSettingsTex;
float4 _GradientSettingsTex_TexelSize;
float4 _GradientSettingsTex_ST;

// sRGB vertex colours to linear (UIGammaToLinear, UnityUI.cginc's exact
// curve) and back.
half3 uie_gamma_to_linear(half3 value) { return FacetSrgbToLinear(value); }
half3 uie_linear_to_gamma(half3 value) { return FacetLinearToSrgb(value); }

// The vertex layout the renderer writes (the semantics give the locations).
struct appdata_t
{
    float4 vertex : POSITION;
    float2 uv : TEXCOORD0;
    float4 color : COLOR;
    float4 idsFlags : TEXCOORD2;                    // ids: x transform, y clip rect, z opacity; w flags
    float4 xformClipPages : TEXCOORD1;              // shader-info pages: transform xy, clip rect zw
    float4 opacityPageSVGSettingIndex : TEXCOORD3;  // xy opacity page, zw SVG setting index (2 bytes)
    UNITY_VERTEX_INPUT_INSTANCE_ID
};

// The flags and rectangles are the same over a primitive, so they are not
// interpolated.
struct v2f
{
    float4 vertex : SV_POSITION;
    float4 uvXY : TEXCOORD0;                        // xy uv, zw position in points
    UIE_V2F_COLOR_T color : COLOR;
    nointerpolation float4 flags : TEXCOORD1;       // text, atlas, custom texture, solid
    nointerpolation float3 svgFlags : TEXCOORD2;    // SVG gradient, custom SVG gradient, setting index
    nointerpolation float4 clipRectOpacityUVs : TEXCOORD3;
#if UIE_SHADER_INFO_IN_VS
    nointerpolation float4 clipRect : TEXCOORD4;
#endif
    UNITY_VERTEX_OUTPUT_STEREO
};

static const float kUIEMeshZ = 0.995f;
static const float kUIEMaskZ = -0.995f;
static const float kUIEVertexLastFlagValue = 10.0f;

// The element's bone -> group transform (3 rows); the group -> world and
// world -> clip transforms are UNITY_MATRIX_V and UNITY_MATRIX_P.
static float3x4 uie_toWorldMat;

// The view-space offset that widens an edge vertex's embedded displacement
// to at least minDisplacement pixels, rounded to whole pixels (not shrunk
// below the exact width along an axis whose noShrink flag is set).
float2 uie_get_border_offset(float4 vertex, float2 embeddedDisplacement, float minDisplacement, bool noShrinkX,
                             bool noShrinkY)
{
    float2 viewDisp = mul(uie_toWorldMat, float4(embeddedDisplacement, 0, 0)).xy;
    float2 pixels = abs(viewDisp * _1PixelClipInvView.zw);
    float2 wanted = max(minDisplacement.xx, pixels);
    float2 rounded = round(wanted);
    if (noShrinkX) rounded.x = max(rounded.x, wanted.x);
    if (noShrinkY) rounded.y = max(rounded.y, wanted.y);
    rounded += step(rounded, minDisplacement - 0.001);
    float2 ratio = clamp(rounded / (pixels + 0.000001), 0.01, 100.0);
    return (ratio - 1.0) * viewDisp;
}

// A clip-space position moved to the nearest pixel corner.
float2 uie_snap_to_integer_pos(float2 clipSpaceXY)
{
    return ((int2)((clipSpaceXY + 1.0) / _1PixelClipInvView.xy + 0.51f)) * _1PixelClipInvView.xy - 1.0;
}

// Discards fragments outside the element's clip rectangle (points) or the
// pass's pixel rectangle.
void uie_fragment_clip(v2f i)
{
#if UIE_SHADER_INFO_IN_VS
    float4 rect = i.clipRect;
#else
    float4 rect = _ClipRects[(int)i.clipRectOpacityUVs.x];
#endif
    float2 pointPos = i.uvXY.zw;
    float2 pixelPos = i.vertex.xy;
    float2 inside = step(rect.xy, pointPos) * step(pointPos, rect.zw) *
                    step(_PixelClipRect.xy, pixelPos) * step(pixelPos, _PixelClipRect.zw);
    clip(inside.x * inside.y - 0.5);
}

// The shader-info texel of entry `id` in page pageXY (both stored as bytes):
// pages are 32 x 8 texels, entries yStride texels high.
float2 uie_decode_shader_info_texel_pos(float2 pageXY, float id, float yStride)
{
    const float pageWidth = 32.0;
    const float pageHeight = 8.0;
    id *= 255.0f;
    pageXY *= 255.0f;
    float column = id % pageWidth;
    float row = (id - column) / pageWidth;
    return float2(pageXY.x * pageWidth + column, pageXY.y * pageHeight + row * yStride);
}

// Loads the vertex's element transform into uie_toWorldMat.
void uie_vert_load_payload(appdata_t v)
{
#if UIE_SHADER_INFO_IN_VS
    float2 texel = uie_decode_shader_info_texel_pos(v.xformClipPages.xy, v.idsFlags.x, 3.0f);
    float4 r0 = tex2Dlod(_ShaderInfoTex, float4((texel + float2(0, 0) + 0.5f) * _ShaderInfoTex_TexelSize.xy, 0, 0));
    float4 r1 = tex2Dlod(_ShaderInfoTex, float4((texel + float2(0, 1) + 0.5f) * _ShaderInfoTex_TexelSize.xy, 0, 0));
    float4 r2 = tex2Dlod(_ShaderInfoTex, float4((texel + float2(0, 2) + 0.5f) * _ShaderInfoTex_TexelSize.xy, 0, 0));
    uie_toWorldMat = float3x4(r0, r1, r2);
#else
    int first = (int)(v.idsFlags.x * 255.0f * 3.0f);
    uie_toWorldMat = float3x4(_Transforms[first], _Transforms[first + 1], _Transforms[first + 2]);
#endif
}

// Two 16-bit values stored as byte pairs (values already scaled to 0..255).
float2 uie_unpack_float2(fixed4 c) { return float2(c.r * 255.0 + c.g, c.b * 255.0 + c.a); }

// Where a ray from inside the unit circle first leaves it.
float2 uie_ray_unit_circle_first_hit(float2 rayStart, float2 rayDir)
{
    float along = dot(-rayStart, rayDir);
    float halfChord = sqrt(1.0f - (dot(rayStart, rayStart) - along * along));
    float tNear = along - halfChord;
    float tFar = along + halfChord;
    float t = min(tNear, tFar);
    if (t < 0.0f) t = max(tNear, tFar);
    return rayStart + rayDir * t;
}

// The radial gradient's parameter at uv (0 at the focus, 1 on the circle).
float uie_radial_address(float2 uv, float2 focus)
{
    uv = (uv - 0.5f) * 2.0f;
    float2 edge = uie_ray_unit_circle_first_hit(focus, normalize(uv - focus)) - focus;
    if (abs(edge.x) > 0.0001f) return (uv.x - focus.x) / edge.x;
    if (abs(edge.y) > 0.0001f) return (uv.y - focus.y) / edge.y;
    return 0.0f;
}

struct GradientLocation
{
    float2 uv;
    float4 location;   // xy atlas position, zw size (texels)
};

// A gradient's settings, 3 texels in row settingIndex: (type: 0 linear,
// 1 radial; address mode: 0 wrap, 1 clamp, 2 mirror; radial focus xy), the
// atlas position and the atlas size (byte pairs).
GradientLocation uie_sample_gradient_location(float settingIndex, float2 uv, sampler2D settingsTex, float2 texelSize)
{
    float2 settingUV = float2(0.5f, settingIndex + 0.5f) * texelSize;
    fixed4 settings = tex2D(settingsTex, settingUV);
    if (settings.x > 0.0f)
        uv = float2(uie_radial_address(uv, (settings.zw - 0.5f) * 2.0f), 0.0);
    int mode = settings.y * 255;
    if (mode == 0) {
        uv.x = fmod(uv.x, 1.0f);
    } else if (mode == 1) {
        uv.x = saturate(uv.x);
    } else if (mode == 2) {
        float m = fmod(uv.x, 2.0f);
        uv.x = m > 1.0f ? 1.0f - fmod(m, 1.0f) : m;
    }
    GradientLocation grad;
    grad.uv = uv;
    float2 step1 = float2(texelSize.x, 0);
    grad.location.xy = uie_unpack_float2(tex2D(settingsTex, settingUV + step1) * 255) + 0.5f;
    grad.location.zw = uie_unpack_float2(tex2D(settingsTex, settingUV + step1 * 2) * 255);
    return grad;
}

// 1 where flags equals value, else 0 (flags is left as it is).
float TestForValue(float value, inout float flags) { return flags == value ? 1.0 : 0.0; }

// Coverage of a signed-distance sample (0.5 = edge), antialiased over one
// pixel's change.
float sdf(float distanceSample)
{
    float smoothing = fwidth(distanceSample);
    return smoothstep(0.5 - smoothing, 0.5 + smoothing, distanceSample);
}

// The vertex colour (linearised unless in gamma space) with the element's
// opacity, and the shader-info uvs of the clip rectangle (xy) and the
// opacity (zw).
float4 uie_std_vert_shader_info(appdata_t v, out UIE_V2F_COLOR_T color)
{
#if UIE_COLORSPACE_GAMMA
    color = v.color;
#else
    color = UIE_V2F_COLOR_T(uie_gamma_to_linear(v.color.rgb), v.color.a);
#endif
    float2 opacityUV = (uie_decode_shader_info_texel_pos(v.opacityPageSVGSettingIndex.xy, v.idsFlags.z, 1.0f) + 0.5f) *
                       _ShaderInfoTex_TexelSize.xy;
#if UIE_SHADER_INFO_IN_VS
    float2 clipRectUV = (uie_decode_shader_info_texel_pos(v.xformClipPages.zw, v.idsFlags.y, 1.0f) + 0.5f) *
                        _ShaderInfoTex_TexelSize.xy;
    color.a *= tex2Dlod(_ShaderInfoTex, float4(opacityUV, 0, 0)).a;
#else
    float2 clipRectUV = float2(v.idsFlags.y * 255.0f, 0.0f);
#endif
    return float4(clipRectUV, opacityUV);
}

v2f uie_std_vert(appdata_t v)
{
    v2f o;
    UNITY_SETUP_INSTANCE_ID(v);
    UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO(o);
    uie_vert_load_payload(v);

    // The vertex kind (one value 1..9 in idsFlags.w).
    float kind = v.idsFlags.w * 255.0f;
    float isCustomSVGGradients = TestForValue(9.0, kind);
    float isSVGGradients = TestForValue(8.0, kind);
    float isEdgeNoShrinkY = TestForValue(7.0, kind);
    float isEdgeNoShrinkX = TestForValue(6.0, kind);
    float isEdge = TestForValue(5.0, kind);
    float isCustomTex = TestForValue(4.0, kind);
    float isAtlasTexBilinear = TestForValue(3.0, kind);
    float isAtlasTexPoint = TestForValue(2.0, kind);
    float isText = TestForValue(1.0, kind);
    float isAtlasTex = isAtlasTexBilinear + isAtlasTexPoint;
    float isSolid = 1.0 - saturate(isText + isAtlasTex + isCustomTex + isSVGGradients + isCustomSVGGradients);

    float2 viewOffset = 0;
    if (isEdge == 1 || isEdgeNoShrinkX == 1 || isEdgeNoShrinkY == 1)
        viewOffset = uie_get_border_offset(v.vertex, v.uv, 1, isEdgeNoShrinkX == 1, isEdgeNoShrinkY == 1);
    v.vertex.xyz = mul(uie_toWorldMat, v.vertex);
    v.vertex.xy += viewOffset;
    o.uvXY.zw = v.vertex.xy;
    o.vertex = UnityObjectToClipPos(v.vertex);
#ifndef UIE_SDF_TEXT
    if (isText == 1) o.vertex.xy = uie_snap_to_integer_pos(o.vertex.xy);
#endif
    o.uvXY.xy = TRANSFORM_TEX(v.uv, _MainTex);
    if (isAtlasTex == 1.0f) o.uvXY.xy *= _MainTex_TexelSize.xy;   // atlas uvs come in texels
#if UIE_SIMPLE_ATLAS
    o.flags = fixed4(isText, isAtlasTex, isCustomTex, isSolid);
#else
    o.flags = fixed4(isText, isAtlasTexBilinear - isAtlasTexPoint, isCustomTex, isSolid);
#endif
    float svgSettingsIndex = v.opacityPageSVGSettingIndex.z * (255.0f * 255.0f) + v.opacityPageSVGSettingIndex.w * 255.0f;
    o.svgFlags = fixed3(isSVGGradients, isCustomSVGGradients, svgSettingsIndex);
    o.clipRectOpacityUVs = uie_std_vert_shader_info(v, o.color);
#if UIE_SHADER_INFO_IN_VS
    o.clipRect = tex2Dlod(_ShaderInfoTex, float4(o.clipRectOpacityUVs.xy, 0, 0));
#endif
    return o;
}

UIE_FRAG_T uie_std_frag(v2f i)
{
    uie_fragment_clip(i);
    float2 uv = i.uvXY.xy;
#if !UIE_SHADER_INFO_IN_VS
    i.color.a *= tex2D(_ShaderInfoTex, i.clipRectOpacityUVs.zw).a;
#endif
    UIE_FRAG_T texColor = (UIE_FRAG_T)i.flags.w;   // solid
#if UIE_SIMPLE_ATLAS
    texColor += tex2D(_MainTex, uv) * i.flags.y;
#else
    texColor += _MainTex.Sample(uie_point_clamp_sampler, uv) * saturate(-i.flags.y);
    texColor += _MainTex.Sample(uie_linear_clamp_sampler, uv) * saturate(i.flags.y);
#endif
#ifdef UIE_SDF_TEXT
    texColor += UIE_FRAG_T(1, 1, 1, sdf(tex2D(_FontTex, uv).a)) * i.flags.x;
#else
    texColor += UIE_FRAG_T(1, 1, 1, tex2D(_FontTex, uv).a) * i.flags.x;
#endif
    texColor += tex2D(_CustomTex, uv) * i.flags.z;
    fixed isSVG = i.svgFlags.x;
    fixed isCustomSVG = i.svgFlags.y;
    if (isSVG == 1.0f || isCustomSVG == 1.0f) {
        float2 atlasTexel = isCustomSVG == 1.0f ? _CustomTex_TexelSize.xy : _MainTex_TexelSize.xy;
        GradientLocation grad = uie_sample_gradient_location(i.svgFlags.z, uv, _GradientSettingsTex,
                                                             _GradientSettingsTex_TexelSize.xy);
        grad.location *= atlasTexel.xyxy;
        float2 gradUV = grad.uv * grad.location.zw + grad.location.xy;
#if UIE_SIMPLE_ATLAS
        texColor += tex2D(_MainTex, gradUV) * isSVG;
#else
        texColor += _MainTex.Sample(uie_linear_clamp_sampler, gradUV) * isSVG;
#endif
        texColor += tex2D(_CustomTex, gradUV) * isCustomSVG;
    }
    return texColor * i.color;
}

#ifndef UIE_CUSTOM_SHADER
v2f vert(appdata_t v) { return uie_std_vert(v); }
UIE_FRAG_T frag(v2f i) : SV_Target { return uie_std_frag(i); }
#endif

#endif // UNITY_UIE_INCLUDED
