// A cubemap reflection through worldRefl and INTERNAL_DATA: the normal map
// bends the reflected direction (WorldReflectionVector).
Shader "Examples/Surface/Reflection" {
  Properties {
    _MainTex ("Texture", 2D) = "white" {}
    _BumpMap ("Normal Map", 2D) = "bump" {}
    _Cube ("Cubemap", Cube) = "" {}
    _Reflectivity ("Reflectivity", Range(0, 1)) = 0.5
  }
  SubShader {
    Tags { "RenderType" = "Opaque" }
    CGPROGRAM
    #pragma surface surf Lambert
    sampler2D _MainTex;
    sampler2D _BumpMap;
    samplerCUBE _Cube;
    half _Reflectivity;
    struct Input {
      float2 uv_MainTex;
      float2 uv_BumpMap;
      float3 worldRefl;
      INTERNAL_DATA
    };
    void surf(Input IN, inout SurfaceOutput o) {
      o.Albedo = tex2D(_MainTex, IN.uv_MainTex).rgb * (1 - _Reflectivity);
      o.Normal = UnpackNormal(tex2D(_BumpMap, IN.uv_BumpMap));
      o.Emission = texCUBE(_Cube, WorldReflectionVector(IN, o.Normal)).rgb * _Reflectivity;
    }
    ENDCG
  }
  Fallback "Diffuse"
}
