// A tessellated Standard surface shader. tessellate:tess picks edge factors
// so that each edge spans about _EdgeLength pixels (UnityEdgeLengthBasedTess),
// tessphong:_Phong rounds the silhouette between the original vertices, and
// the vertex modifier `disp`, which with tessellation runs in the domain
// stage on every generated vertex, moves it along its normal by a height
// texture. Needs shader model 4.6: facet adds hull and domain stages to
// ForwardBase, ForwardAdd and the addshadow ShadowCaster.
Shader "Examples/Surface/Tessellation" {
  Properties {
    _MainTex ("Albedo", 2D) = "white" {}
    _HeightTex ("Height", 2D) = "gray" {}
    _Displacement ("Displacement", Range(0, 0.5)) = 0.1
    _EdgeLength ("Edge length (pixels)", Range(2, 50)) = 12
    _Phong ("Phong strength", Range(0, 1)) = 0.5
    _Glossiness ("Smoothness", Range(0, 1)) = 0.4
  }
  SubShader {
    Tags { "RenderType" = "Opaque" }
    CGPROGRAM
    #pragma surface surf Standard addshadow fullforwardshadows vertex:disp tessellate:tess tessphong:_Phong
    #pragma target 4.6
    #include "Tessellation.cginc"

    // As small as tessellation allows: every member travels through the
    // hull and domain stages.
    struct appdata {
      float4 vertex : POSITION;
      float4 tangent : TANGENT;
      float3 normal : NORMAL;
      float2 texcoord : TEXCOORD0;
    };

    sampler2D _MainTex, _HeightTex;
    float _Displacement, _EdgeLength, _Phong;
    half _Glossiness;

    float4 tess(appdata v0, appdata v1, appdata v2) {
      return UnityEdgeLengthBasedTess(v0.vertex, v1.vertex, v2.vertex, _EdgeLength);
    }

    void disp(inout appdata v) {
      float height = tex2Dlod(_HeightTex, float4(v.texcoord.xy, 0, 0)).r;
      v.vertex.xyz += v.normal * (height - 0.5) * _Displacement;
    }

    struct Input {
      float2 uv_MainTex;
    };

    void surf(Input IN, inout SurfaceOutputStandard o) {
      o.Albedo = tex2D(_MainTex, IN.uv_MainTex).rgb;
      o.Smoothness = _Glossiness;
      o.Metallic = 0;
    }
    ENDCG
  }
  Fallback "Diffuse"
}
