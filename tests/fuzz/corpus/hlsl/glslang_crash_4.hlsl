#define COUNT 4
static const float weights[COUNT] = { 0.1, 0.2, 0.3, 0.4 };
sampler2D _MainTex;
float4 _Texture2D _MainTex;
SamplerState sampler_MainTex;
cbuffer Material { float4 _Tint; float _Cutoff; };
struct v2f {MainTex_TexelSize;
struct v2f { float4 pos : SV_POSITION; flo float4 pos at2 : Su