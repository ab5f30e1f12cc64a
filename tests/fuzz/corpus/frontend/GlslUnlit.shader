// A GLSLPROGRAM block: raw GLSL 450 with VERTEX/FRAGMENT sections, as in Unity.
Shader "Examples/GlslUnlit" {
    Properties {
        _Color ("Color", Color) = (0.2, 0.6, 1, 1)
    }
    SubShader {
        Pass {
            GLSLPROGRAM
            layout(set = 2, binding = 0) uniform Material { vec4 _Color; };
            #ifdef VERTEX
            layout(location = 0) in vec4 in_position;
            void main() { gl_Position = in_position; }
            #endif
            #ifdef FRAGMENT
            layout(location = 0) out vec4 out_color;
            void main() { out_color = _Color; }
            #endif
            ENDGLSL
        }
    }
}
