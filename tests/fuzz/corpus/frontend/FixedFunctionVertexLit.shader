// A fixed-function vertex-lit shader, the way Unity's legacy VertexLit
// shader is written: per-vertex lighting from up to 8 lights with a
// separate Blinn-Phong specular, then one texture stage. facet lowers it to
// HLSL at import (see `facetc -E`); VertexLitByHand.shader is the same
// lighting written as a vertex/fragment program.
Shader "Examples/FixedFunctionVertexLit" {
    Properties {
        _Color ("Main Color", Color) = (1, 1, 1, 1)
        _SpecColor ("Specular Color", Color) = (0.5, 0.5, 0.5, 1)
        _Emission ("Emissive Color", Color) = (0, 0, 0, 0)
        _Shininess ("Shininess", Range(0.01, 1)) = 0.4
        _MainTex ("Base (RGB)", 2D) = "white" {}
    }
    SubShader {
        Tags { "RenderType" = "Opaque" }
        Pass {
            Tags { "LightMode" = "Vertex" }
            Material {
                Diffuse [_Color]
                Ambient [_Color]
                Shininess [_Shininess]
                Specular [_SpecColor]
                Emission [_Emission]
            }
            Lighting On
            SeparateSpecular On
            SetTexture [_MainTex] {
                constantColor [_Color]
                Combine texture * primary DOUBLE, texture * constant
            }
        }
    }
}
