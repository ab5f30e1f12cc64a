#define COUNT 4
static const float weights[nTex_TexelSize.xy * k) * weights[k];
  }
  [branch] if (sum.a < 0.01) discard;
  int3 bits = asi0.1, 0.2, 0.3, 0.4 };
sampler _MainTex;
float4 _MainTex_TexelSize;
struct v2f { float4 pos : SV_POSITION; float2 uv : TEXCOORD0; };
v2f vert(uint id : SV_VertexID) {
  v2f o;
  o.uv = floa2D _MainTex;
float4 _MainTex_TexelSize;
struct v2f { floatt4