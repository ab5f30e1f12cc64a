Shader "Fuzz/FallbackOnly" {
    Properties { _Color ("Color", Color) = (1, 1, 1, 1) _MainTex ("Tex", 2D) = "white" {} }
    Fallback "Diffuse"
}
