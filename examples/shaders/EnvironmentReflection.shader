// The reflection probe read as Unity's Standard shader reads it: the
// environment cube unity_SpecCube0 at the mip Unity_GlossyEnvironment picks
// for a perceptual roughness, HDR-decoded, times a reflectance. With
// reflectance 1 it is a metal whose Fresnel is 1 everywhere, without the
// Standard BRDF's surfaceReduction: in a uniform environment every pixel
// shows the environment's radiance itself, whatever the roughness.
Shader "Examples/EnvironmentReflection" {
  Properties {
    _Color ("Reflectance", Color) = (1, 1, 1, 1)
    _Roughness ("Perceptual roughness", Range(0, 1)) = 0.5
  }
  SubShader {
    Tags { "RenderType" = "Opaque" }
    Pass {
      Tags { "LightMode" = "ForwardBase" }
      CGPROGRAM
      #pragma vertex vert
      #pragma fragment frag
      #include "UnityCG.cginc"
      #include "UnityImageBasedLighting.cginc"

      half4 _Color;
      half _Roughness;

      struct v2f {
        float4 pos : SV_POSITION;
        float3 worldPos : TEXCOORD0;
        float3 worldNormal : TEXCOORD1;
      };

      v2f vert(appdata_base v) {
        v2f o;
        o.pos = UnityObjectToClipPos(v.vertex);
        o.worldPos = mul(unity_ObjectToWorld, v.vertex).xyz;
        o.worldNormal = UnityObjectToWorldNormal(v.normal);
        return o;
      }

      float4 frag(v2f i) : SV_Target {
        float3 n = normalize(i.worldNormal);
        float3 v = normalize(UnityWorldSpaceViewDir(i.worldPos));
        Unity_GlossyEnvironmentData g;
        g.roughness = _Roughness;
        g.reflUVW = reflect(-v, n);
        half3 reflected = Unity_GlossyEnvironment(UNITY_PASS_TEXCUBE(unity_SpecCube0), unity_SpecCube0_HDR, g);
        return float4(reflected * _Color.rgb, 1);
      }
      ENDCG
    }
  }
}
