// The camera's sky background (a scene's camera "clear": "sky"): the same
// procedural sky as the ambient SH and the environment cube (sky_sh.h):
// radiance horizon -> zenith linearly in the view direction's y above the
// horizon, horizon -> ground linearly in -y below, times the intensity;
// and the sky's sun, a disc of the given radiance.
// Drawn by the runtime on a full-screen quad before the scene.
Shader "Hidden/Facet/ProceduralSky" {
    Properties {
        _Zenith ("Zenith", Color) = (0.2, 0.45, 0.8, 1)
        _Horizon ("Horizon", Color) = (0.75, 0.8, 0.85, 1)
        _Ground ("Ground", Color) = (0.3, 0.27, 0.22, 1)
        _Intensity ("Intensity", Float) = 1
        _SunDirection ("Direction towards the sun", Vector) = (0, 1, 0, 0)
        _SunRadiance ("Sun radiance (linear, 0: no sun)", Vector) = (0, 0, 0, 0)
        _SunCos ("Cosine of the sun's angular radius", Float) = 1
    }
    SubShader {
        Cull Off ZWrite Off ZTest Always
        Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"

            float4 _Zenith, _Horizon, _Ground;
            float _Intensity;
            float4 _SunDirection, _SunRadiance;
            float _SunCos;

            struct v2f {
                float4 pos : SV_POSITION;
                float2 ndc : TEXCOORD0;
            };

            // The runtime's blit matrices make the quad cover the screen.
            v2f vert(appdata_img v) {
                v2f o;
                o.pos = UnityObjectToClipPos(v.vertex);
                o.ndc = o.pos.xy / o.pos.w;
                return o;
            }

            float4 frag(v2f i) : SV_Target {
                // The view ray through this pixel (an orthographic camera's
                // are all its forward): right-handed view space, then the
                // left-handed camera's world rotation.
                float4 ray = mul(unity_CameraInvProjection, float4(i.ndc, 1.0, 1.0));
                float3 view = unity_OrthoParams.w > 0.5 ? float3(0.0, 0.0, -1.0) : ray.xyz / ray.w;
                float3 dir = normalize(mul((float3x3)unity_CameraToWorld, float3(view.xy, -view.z)));
                float3 sky = dir.y >= 0.0 ? lerp(_Horizon.rgb, _Zenith.rgb, dir.y) : lerp(_Horizon.rgb, _Ground.rgb, -dir.y);
                // The sun's disc, linear across the outer tenth of its radius (sky_sh.h's sun_radiance).
                float radius = acos(min(_SunCos, 1.0));
                float angle = acos(clamp(dot(dir, normalize(_SunDirection.xyz)), -1.0, 1.0));
                float disc = radius > 0.0 ? saturate((radius - angle) / (0.1 * radius)) : 0.0;
                return float4(sky * _Intensity + _SunRadiance.rgb * disc, 1.0);
            }
            ENDCG
        }
    }
}
