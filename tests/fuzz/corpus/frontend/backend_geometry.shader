Shader "Test/Geometry" { SubShader { Pass {
CGPROGRAM
#pragma vertex vert
#pragma geometry geom
#pragma fragment frag
#pragma target 4.0
struct v2g { float4 pos : SV_POSITION; float2 uv : TEXCOORD0; float3 n : NORMAL; };
struct g2f { float4 pos : SV_POSITION; float2 uv : TEXCOORD0; float3 n : NORMAL; };
v2g vert(float4 p : POSITION, float2 uv : TEXCOORD0, float3 n : NORMAL) { v2g o; o.pos = p; o.uv = uv; o.n = n; return o; }
[maxvertexcount(3)]
void geom(triangle v2g input[3], inout TriangleStream<g2f> stream) {
  for (int i = 0; i < 3; i++) { g2f o; o.pos = input[i].pos; o.uv = input[i].uv; o.n = input[i].n; stream.Append(o); }
}
fixed4 frag(g2f i) : SV_Target { return float4(i.uv, i.n.x, 1); }
ENDCG
} } }
