// facet's own "Legacy Shaders/Transparent/VertexLit": VertexLit blended over
// what is behind it by its alpha, without writing depth; it casts no shadow.
Shader "Legacy Shaders/Transparent/VertexLit" {
    Properties {
        _Color ("Main Color", Color) = (1, 1, 1, 1)
        _SpecColor ("Spec Color", Color) = (1, 1, 1, 0)
        _Emission ("Emissive Color", Color) = (0, 0, 0, 0)
        _Shininess ("Shininess", Range(0.1, 1)) = 0.7
        _MainTex ("Base (RGB) Trans (A)", 2D) = "white" {}
    }
    SubShader {
        Tags { "Queue" = "Transparent" "IgnoreProjector" = "True" "RenderType" = "Transparent" }
        LOD 100
        ZWrite Off
        Blend SrcAlpha OneMinusSrcAlpha
        ColorMask RGB

        Pass {
            Tags { "LightMode" = "Vertex" }
            Lighting On
            SeparateSpecular On
            Material {
                Ambient [_Color]
                Diffuse [_Color]
                Emission [_Emission]
                Shininess [_Shininess]
                Specular [_SpecColor]
            }
            SetTexture [_MainTex] {
                Combine texture * primary DOUBLE, texture * primary
            }
        }
    }
}
