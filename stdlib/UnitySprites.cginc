// The sprite shaders' common vertex/fragment programs (SpriteVert,
// SpriteFrag). SpriteRenderer state is per-renderer data in Unity
// (_RendererColor, _Flip, _EnableExternalAlpha); facet has no sprite
// renderer, so they are loose material uniforms ("$Globals"): the
// Sprites shaders declare them as hidden properties with defaults (1,1,1,1),
// (1,1,1,1) and 0, which the runtime fills by name. Instancing is off, so
// they are never instanced arrays.
#ifndef UNITY_SPRITES_INCLUDED
#define UNITY_SPRITES_INCLUDED

#include "UnityCG.cginc"

// The tint: the material's colour times the renderer's.
fixed4 _Color;
fixed4 _RendererColor;
// Per-axis mirroring (+-1) and whether _AlphaTex supplies the alpha.
fixed2 _Flip;
float _EnableExternalAlpha;

// Sprite mesh data and interpolators (the semantics give the locations).
struct appdata_t
{
    float4 vertex : POSITION;
    float2 texcoord : TEXCOORD0;
    float4 color : COLOR;
    UNITY_VERTEX_INPUT_INSTANCE_ID
};
struct v2f
{
    float4 vertex : SV_POSITION;
    float2 texcoord : TEXCOORD0;
    float4 color : COLOR;
    UNITY_VERTEX_OUTPUT_STEREO
};

// Mirrors the sprite in x and/or y (flip = +-1 per axis) in object space.
inline float4 UnityFlipSprite(in float3 pos, in fixed2 flip) { return float4(pos.xy * flip, pos.z, 1.0); }

v2f SpriteVert(appdata_t input)
{
    v2f o;
    UNITY_SETUP_INSTANCE_ID(input);
    UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO(o);
    o.vertex = UnityObjectToClipPos(UnityFlipSprite(input.vertex.xyz, _Flip));
    o.texcoord = input.texcoord;
    o.color = input.color * _Color * _RendererColor;
#ifdef PIXELSNAP_ON
    o.vertex = UnityPixelSnap(o.vertex);
#endif
    return o;
}

sampler2D _MainTex;
sampler2D _AlphaTex;   // ETC1 split alpha (red channel), used under ETC1_EXTERNAL_ALPHA

fixed4 SampleSpriteTexture(float2 uv)
{
    fixed4 color = tex2D(_MainTex, uv);
#if ETC1_EXTERNAL_ALPHA
    color.a = lerp(color.a, tex2D(_AlphaTex, uv).r, _EnableExternalAlpha);
#endif
    return color;
}

// Premultiplied output (the sprite shaders blend One OneMinusSrcAlpha).
fixed4 SpriteFrag(v2f input) : SV_Target
{
    fixed4 c = SampleSpriteTexture(input.texcoord) * input.color;
    c.rgb *= c.a;
    return c;
}

#endif // UNITY_SPRITES_INCLUDED
