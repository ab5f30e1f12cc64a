/* Category, UsePass, GrabPass, include scopes and every program language. */
Shader "Tests/Scopes" {
  HLSLINCLUDE
  #define SHADER_SCOPE 1
  ENDHLSL
  Category {
    Tags { "Queue"="Transparent+1" "IgnoreProjector"="True" }
    Blend SrcAlpha One
    ColorMask RGB
    Cull Off Lighting Off ZWrite Off
    SubShader {
      Tags { "RenderType"="Transparent" }
      HLSLINCLUDE
      #define SUBSHADER_SCOPE 1
      ENDHLSL
      GrabPass { "_BackgroundTexture" }
      GrabPass { }
      UsePass "Legacy Shaders/VertexLit/SHADOWCASTER"
      Pass {
        Name "Main"
        Cull Back
        HLSLPROGRAM
        #pragma vertex vert
        #pragma fragment frag
        #pragma geometry geom
        #pragma multi_compile __ FOO_ON
        ENDHLSL
      }
    }
  }
  SubShader {
    Pass {
      GLSLPROGRAM
      #if defined(VERTEX)
      void main() { gl_Position = vec4(0.0); }
      #elif defined (FRAGMENT)
      out vec4 color;
      void main() { color = vec4(1.0); }
      #endif
      ENDGLSL
    }
  }
  Fallback Off
}
