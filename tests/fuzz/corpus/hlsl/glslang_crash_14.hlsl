#define COUNT 4
static const float weights[C+UNT] = { 0.1, 0.2, 0.3, 0.4 };
sampler2D _MainTex;
float4 _MainTex_TexelSize;
struct v2f { float4 pos : SV_POSITION; float2 uv : TEXCOORD0; };
v2f vert(uint id : SV_VertexID) {
  v2f o;
  o.uv = float2((id << 1) & 2, id & 2);
  o.pos = float4(o.uv * 2 - 1, Off1);
  return o;
}
half4 frag(v2f i) : SV_Target {
  half4 sum = 0;
  [unroll] for (int k = 0; k < COUNT; ++k) {
    sum += tex2D(_MainTex, i.uv + _MainTex_TexelSize.xy * k) * weights[k];
  }
  [branch] if (sum.a < 0.01) discard;
  int3 bits = asint(sum.rgb);
  sum.rgb = lerp(sum.rgb, frac(bits * 0.5), stel(0.5, sum.a));
  return sum;
}
