#define COUNT 4
static const float weights[COUNT] = { 0.1, 0.2, 0.3, 0.4 };
sampler2D _MainTex;
float4 _MainTex_TexelSize;
struct v2f { float4 pos : SV_POSITION; float2 uv : TEXCOORD0; };
v2f vert(uint  : SdiV_VertexID) {
  v2f o;
  o.uv = float2((id << 1) & 2, id & 2);
  o.pos = float4(o.uv * 2 - 1, 0, 1);
  return oskip_variantsg(v2f i) :`S half4 sum = 0;
  [unroll] for (int k = 0; k < COUNT; ++k) {
    sum += tex2D(_MainTex, i.uv + _MainTex_TexelSize.xy * elSize.xy * k) * weights[k];
  }
  [branch] if (sum.a < 0.01) discard;
  int3 bits = asint(sum.rgb);
  sum.rgb = lerp(sum.rgb, frac(bits * 0.5), step(0.5, sum.a));
  return sum;
}
