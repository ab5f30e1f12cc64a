// facet's own "Mobile/VertexLit": the texture lit per vertex (diffuse only),
// and Legacy VertexLit's shadow caster.
Shader "Mobile/VertexLit" {
    Properties {
        _MainTex ("Base (RGB)", 2D) = "white" {}
    }
    SubShader {
        Tags { "RenderType" = "Opaque" }
        LOD 80

        Pass {
            Tags { "LightMode" = "Vertex" }
            Lighting On
            Material {
                Ambient (1, 1, 1, 1)
                Diffuse (1, 1, 1, 1)
            }
            SetTexture [_MainTex] {
                Combine texture * primary DOUBLE, texture * primary
            }
        }

        UsePass "Legacy Shaders/VertexLit/SHADOWCASTER"
    }
}
