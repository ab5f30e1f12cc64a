// A custom lighting model with its own _GI function: wrapped diffuse whose
// indirect light is the ambient SH scaled by a property.
Shader "Examples/Surface/CustomGI" {
  Properties {
    _MainTex ("Texture", 2D) = "white" {}
    _Wrap ("Wrap", Range(0, 1)) = 0.5
    _AmbientScale ("Ambient Scale", Range(0, 2)) = 1
  }
  SubShader {
    Tags { "RenderType" = "Opaque" }
    CGPROGRAM
    #pragma surface surf WrapGI
    sampler2D _MainTex;
    half _Wrap;
    half _AmbientScale;
    struct Input {
      float2 uv_MainTex;
    };
    half4 LightingWrapGI(SurfaceOutput s, UnityGI gi) {
      half wrapped = saturate((dot(s.Normal, gi.light.dir) + _Wrap) / (1 + _Wrap));
      half4 c;
      c.rgb = s.Albedo * gi.light.color * wrapped;
    #ifdef UNITY_LIGHT_FUNCTION_APPLY_INDIRECT
      c.rgb += s.Albedo * gi.indirect.diffuse;
    #endif
      c.a = s.Alpha;
      return c;
    }
    void LightingWrapGI_GI(SurfaceOutput s, UnityGIInput data, inout UnityGI gi) {
      gi = UnityGlobalIllumination(data, 1.0, s.Normal);
      gi.indirect.diffuse *= _AmbientScale;
    }
    void surf(Input IN, inout SurfaceOutput o) {
      o.Albedo = tex2D(_MainTex, IN.uv_MainTex).rgb;
    }
    ENDCG
  }
  Fallback "Diffuse"
}
