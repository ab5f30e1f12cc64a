// Post-processing passes in the style of OnRenderImage/Graphics.Blit:
// pass 0 greyscale, pass 1 a 9-tap box blur, pass 2 depth visualisation,
// pass 3 a vignette with a warm or cool tint (colour grading's simplest form).
Shader "Hidden/Examples/ImageEffects" {
    Properties {
        _MainTex ("Source", 2D) = "white" {}
        _Amount ("Amount", Range(0, 1)) = 1
        _BlurRadius ("Blur Radius (texels)", Float) = 1
        _Vignette ("Vignette darkening at the corners", Range(0, 1)) = 0.35
        _Tint ("Tint", Color) = (1, 1, 1, 1)
    }
    CGINCLUDE
    #include "UnityCG.cginc"
    sampler2D _MainTex;
    float4 _MainTex_TexelSize;
    float _Amount;
    float _BlurRadius;
    float _Vignette;
    float4 _Tint;

    struct v2f {
        float4 pos : SV_POSITION;
        float2 uv : TEXCOORD0;
    };

    v2f vert_img_fullscreen(appdata_img v) {
        v2f o;
        o.pos = UnityObjectToClipPos(v.vertex);
        o.uv = v.texcoord;
        return o;
    }
    ENDCG

    SubShader {
        Cull Off ZWrite Off ZTest Always
        Pass {
            Name "GREYSCALE"
            CGPROGRAM
            #pragma vertex vert_img_fullscreen
            #pragma fragment frag
            fixed4 frag(v2f i) : SV_Target {
                fixed4 c = tex2D(_MainTex, i.uv);
                fixed grey = Luminance(c.rgb);
                return fixed4(lerp(c.rgb, grey.xxx, _Amount), c.a);
            }
            ENDCG
        }
        Pass {
            Name "BLUR"
            CGPROGRAM
            #pragma vertex vert_img_fullscreen
            #pragma fragment frag
            fixed4 frag(v2f i) : SV_Target {
                float2 step = _MainTex_TexelSize.xy * _BlurRadius;
                fixed4 sum = 0;
                for (int y = -1; y <= 1; y++)
                    for (int x = -1; x <= 1; x++)
                        sum += tex2D(_MainTex, i.uv + float2(x, y) * step);
                return sum / 9.0f;
            }
            ENDCG
        }
        Pass {
            Name "DEPTH"
            CGPROGRAM
            #pragma vertex vert_img_fullscreen
            #pragma fragment frag
            sampler2D _CameraDepthTexture;
            fixed4 frag(v2f i) : SV_Target {
                float depth = Linear01Depth(UNITY_SAMPLE_DEPTH(tex2D(_CameraDepthTexture, i.uv)));
                return fixed4(depth.xxx, 1);
            }
            ENDCG
        }
        Pass {
            Name "VIGNETTE"
            CGPROGRAM
            #pragma vertex vert_img_fullscreen
            #pragma fragment frag
            float4 frag(v2f i) : SV_Target {
                float4 c = tex2D(_MainTex, i.uv);
                // 1 at the centre, 1 - _Vignette at the corners, smooth in between.
                float2 d = (i.uv - 0.5) * 2.0;
                float fall = saturate(dot(d, d) * 0.5);
                return float4(c.rgb * _Tint.rgb * (1.0 - _Vignette * fall * fall), c.a);
            }
            ENDCG
        }
    }
    Fallback Off
}
