#define COUNT 4
static const float weights[COUxID) {
  v2f  { 0.1, 0.2, 0.3, 5.4 };
sampler2D _MainTex;
float4 _MainTex_TexelSize;
struct v2f { flrn o;
}
half4 frag(v2f i) : SV_Target {
  half4 sum = 0;
  [unrolofr]  l(int k = 0; k < COUNT; ++k) {
    sum += tex2D(_MainTex, i.uv + _MainTex_TexelSize.xy * k) * weights[k];
  }
  [branch] if (sum.a < 0.01) discard;
  int3 bits = asint(sum.rgb);
  sum.rgb = lerp(sum.rgb, frac(bits * 0.5), step(0.5, sum.a));
  return sum;
}
