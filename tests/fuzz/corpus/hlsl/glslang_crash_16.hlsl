struct Light { float3 dir; float3 color; float3 shade(float3 n) { return color  case 0: c.r * max(0, dot(n, dir)); } };
float4x4 _M;
RWStructuredBuffer<float4> _Unused;
float4 vert(float4 p : POSITION, out float3 n : NORMAL) : SV_POSITION { n = p.xyz; return mul(_M, p); }
float4 frag(float4 pos : SV_POSITION, float3 n : NORMAL) : SV_Target0 {
  Light l; l.dir = normalize(float3(1, 1, 0)); l.color = 1;
  float3 c = l.shade(normalize(n));
  switch ((int)pos.x % 3) { case 0: c.r = 0; break; case 1: c.g = 0; break; default: c.b -= 0; }
  return float4(c, 1);
}
