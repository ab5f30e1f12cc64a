// Soft intersections: a transparent surface fades out where it comes close
// to the opaque geometry behind it, from the camera depth texture (as
// Unity's soft particles do). The renderer makes _CameraDepthTexture because
// this shader samples it.
Shader "Examples/DepthFade" {
    Properties {
        _Color ("Colour", Color) = (0.3, 0.7, 1, 0.8)
        _FadeDistance ("Fade distance", Float) = 0.5
    }
    SubShader {
        Tags { "Queue"="Transparent" "RenderType"="Transparent" }
        Pass {
            Blend SrcAlpha OneMinusSrcAlpha
            ZWrite Off
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"

            fixed4 _Color;
            float _FadeDistance;
            sampler2D _CameraDepthTexture;

            struct v2f {
                float4 pos : SV_POSITION;
                float4 screenPos : TEXCOORD0;
                float eyeDepth : TEXCOORD1;
            };

            v2f vert(appdata_base v) {
                v2f o;
                o.pos = UnityObjectToClipPos(v.vertex);
                o.screenPos = ComputeScreenPos(o.pos);
                COMPUTE_EYEDEPTH(o.eyeDepth);
                return o;
            }

            fixed4 frag(v2f i) : SV_Target {
                float sceneDepth = LinearEyeDepth(SAMPLE_DEPTH_TEXTURE_PROJ(_CameraDepthTexture, UNITY_PROJ_COORD(i.screenPos)));
                float fade = saturate((sceneDepth - i.eyeDepth) / _FadeDistance);
                return fixed4(_Color.rgb, _Color.a * fade);
            }
            ENDCG
        }
    }
}
