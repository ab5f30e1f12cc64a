#include "UnityCG.cginc"
#pragma multi_compile_fog
#pragma multi_compile __ FANCY
fixed4 _Color;
struct v2f { float4 pos : SV_POSITION; float3 normal : TEXCOORD0; UNITY_FOG_COORDS(1) };
v2f vert(appdata_base v) {
  v2f o;
  o.pos = UnityObjectToClipPos(v.vertex);
  o.normal = UnityObjectToWorldNormal(v.normal);
  UNITY_TRANSFER_FOG(o, o.pos);
  return o;
}
fixed4 frag(v2f i) : SV_Target {
  fixed4 c = _Color * (0.5 + 0.5 * i.normal.y);
#ifdef FANCY
  c.rgb = GammaToLinearSpace(c.rgb);
#endif
  UNITY_APPLY_FOG(i.fogCoord, c);
  return c;
}
