// A Lambert surface shader whose vertex modifier inflates the mesh and
// passes a custom value to surf.
Shader "Examples/Surface/LambertVertex" {
  Properties {
    _MainTex ("Texture", 2D) = "white" {}
    _Amount ("Extrusion", Range(0, 0.1)) = 0.02
  }
  SubShader {
    Tags { "RenderType" = "Opaque" }
    CGPROGRAM
    #pragma surface surf Lambert vertex:vert
    sampler2D _MainTex;
    float _Amount;
    struct Input {
      float2 uv_MainTex;
      float height;
    };
    void vert(inout appdata_full v, out Input o) {
      UNITY_INITIALIZE_OUTPUT(Input, o);
      v.vertex.xyz += v.normal * _Amount;
      o.height = v.vertex.y;
    }
    void surf(Input IN, inout SurfaceOutput o) {
      o.Albedo = tex2D(_MainTex, IN.uv_MainTex).rgb * saturate(0.5 + IN.height);
    }
    ENDCG
  }
  Fallback "Diffuse"
}
