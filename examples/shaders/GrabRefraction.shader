// Glass that bends what is behind it: `GrabPass { }` copies the screen into
// _GrabTexture before the object is drawn, and the object samples it at its
// own screen position (ComputeGrabScreenPos) moved along its view-space
// normal, tinted. With _Distortion 0 and a white tint it is invisible.
Shader "Examples/GrabRefraction" {
    Properties {
        _Tint ("Tint", Color) = (0.85, 0.95, 1, 1)
        _Distortion ("Distortion", Range(0, 0.3)) = 0.08
    }
    SubShader {
        Tags { "Queue" = "Transparent" "RenderType" = "Transparent" }
        GrabPass { }
        Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"

            sampler2D _GrabTexture;
            fixed4 _Tint;
            float _Distortion;

            struct v2f {
                float4 pos : SV_POSITION;
                float4 grab : TEXCOORD0;
                float3 viewNormal : TEXCOORD1;
            };

            v2f vert(appdata_base v) {
                v2f o;
                o.pos = UnityObjectToClipPos(v.vertex);
                o.grab = ComputeGrabScreenPos(o.pos);
                o.viewNormal = mul((float3x3)UNITY_MATRIX_IT_MV, v.normal);
                return o;
            }

            fixed4 frag(v2f i) : SV_Target {
                float2 uv = i.grab.xy / i.grab.w + normalize(i.viewNormal).xy * _Distortion;
                return tex2D(_GrabTexture, uv) * _Tint;
            }
            ENDCG
        }
    }
}
