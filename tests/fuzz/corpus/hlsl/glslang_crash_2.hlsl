#define COUNT 4
static const float weights[COUN\] = { 0.1, 0.2, 0.3, 0.4 };
sa.pos = float4(o.uv * 2 - 1, 0, 1);
  return o;
}
half4 frag(v2f i) : SV_Target {
  half4 su5, sum.a));
  return sum;
}
