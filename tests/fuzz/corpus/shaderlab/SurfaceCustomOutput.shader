// A user output struct and a legacy lighting function (s, lightDir, atten):
// toon-ramped diffuse.
Shader "Examples/Surface/CustomOutput" {
  Properties {
    _MainTex ("Texture", 2D) = "white" {}
    _Steps ("Steps", Range(1, 8)) = 3
  }
  SubShader {
    Tags { "RenderType" = "Opaque" }
    CGPROGRAM
    #pragma surface surf Toon noforwardadd
    sampler2D _MainTex;
    half _Steps;
    struct ToonOutput {
      fixed3 Albedo;
      fixed3 Normal;
      fixed3 Emission;
      fixed Alpha;
      half Rim;
    };
    struct Input {
      float2 uv_MainTex;
      float3 viewDir;
    };
    half4 LightingToon(ToonOutput s, half3 lightDir, half atten) {
      half ndotl = saturate(dot(s.Normal, lightDir));
      half ramp = floor(ndotl * _Steps) / _Steps;
      half4 c;
      c.rgb = s.Albedo * _LightColor0.rgb * ramp * atten + s.Rim;
      c.a = s.Alpha;
      return c;
    }
    void surf(Input IN, inout ToonOutput o) {
      o.Albedo = tex2D(_MainTex, IN.uv_MainTex).rgb;
      o.Rim = pow(1 - saturate(dot(normalize(IN.viewDir), o.Normal)), 4) * 0.5;
    }
    ENDCG
  }
}
