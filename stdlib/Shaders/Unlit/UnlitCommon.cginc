// The one program of facet's Unlit shaders: the texture (or, with
// UNLIT_COLOR_ONLY, _Color alone), cut below _Cutoff alpha with UNLIT_CUTOUT,
// then fog; alpha 1 unless UNLIT_BLENDED.
#ifndef FACET_UNLIT_COMMON_INCLUDED
#define FACET_UNLIT_COMMON_INCLUDED

#include "UnityCG.cginc"

struct unlit_v2f {
    float4 pos : SV_POSITION;
    float2 uv : TEXCOORD0;
    UNITY_FOG_COORDS(1)
    UNITY_VERTEX_OUTPUT_STEREO
};

#ifdef UNLIT_COLOR_ONLY
fixed4 _Color;
#else
sampler2D _MainTex;
float4 _MainTex_ST;
#endif
#ifdef UNLIT_CUTOUT
fixed _Cutoff;
#endif

unlit_v2f vert(appdata_base v) {
    unlit_v2f o;
    UNITY_SETUP_INSTANCE_ID(v);
    UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO(o);
    o.pos = UnityObjectToClipPos(v.vertex);
#ifdef UNLIT_COLOR_ONLY
    o.uv = 0;
#else
    o.uv = TRANSFORM_TEX(v.texcoord, _MainTex);
#endif
    UNITY_TRANSFER_FOG(o, o.pos);
    return o;
}

fixed4 frag(unlit_v2f i) : SV_Target {
#ifdef UNLIT_COLOR_ONLY
    fixed4 col = _Color;
#else
    fixed4 col = tex2D(_MainTex, i.uv);
#endif
#ifdef UNLIT_CUTOUT
    clip(col.a - _Cutoff);
#endif
    UNITY_APPLY_FOG(i.fogCoord, col);
#ifndef UNLIT_BLENDED
    UNITY_OPAQUE_ALPHA(col.a);  // opaque and cutout draws write alpha 1; blended ones keep it
#endif
    return col;
}

#endif
