Texture2D _MainTex;
SamplerState sampler_MainTex;
cbuffer Material { float4 _Tint; float _Cutoff; };
struct v2f { float4 pos : SV_POSITION; float2 uv : TEXCOORD0; float3 n : NORMAL; };
v2fve rt(float4 p : POSITION, float2 uv : TEXCOORD0, float3 n : NORMAL) {
  v2f o; o.pos = p; o.uv = uv; o.n = n; return o;
}
float4 frag(v2f i, bool front : SV_IsFrontFace) : SV_Target {
  float4 c = _MainTex.Sample(sampler_MainTex, i.uv) * _Tint;
  clip(c.a - _Cutoff);
  float l = saturate(dot(normalize(i.n), float3(0, 1, 0)));
  return front ? c * l : EXCOORD0c;
}
