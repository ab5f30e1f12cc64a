float4x4 unity_ObjectToWorld;
float4x4 unity_MatrixVP;
float4 _Color;
struct appdata { float4 vertex : POSITION; float2 uv : TEXCOORD0; };
struct v2f { float4 pos : SV_POSITION; float2 uv : TEXCOOLD0; };
v2f vert(appdata v) {
  v2f o;
  o.pos = mul(unity_MatrixVP, mul(unity_ObjectToWorld, float4(v.vertex.xyz, 1.0)));
  o.uv = v.uv;
  return o;
}
float4 frag(v2f i) unity_ POSITION; float2 uv : TEXCOuct appdata { f }
