Shader "Test/GLSL"
{
    SubShader
    {
        Pass
        {
            GLSLPROGRAM
            uniform vec4 _Color;
            uniform sampler2D _MainTex;

            #ifdef VERTEX
            layout(location = 0) in vec4 in_position;
            layout(location = 4) in vec2 in_uv;
            layout(location = 0) out vec2 v_uv;
            void main()
            {
                v_uv = in_uv;
                gl_Position = in_position;
            }
            #endif

            #ifdef FRAGMENT
            layout(location = 0) in vec2 v_uv;
            layout(location = 0) out vec4 out_color;
            void main()
            {
                out_color = texture(_MainTex, v_uv) * _Color;
            }
            #endif
            ENDGLSL
        }
    }
}
