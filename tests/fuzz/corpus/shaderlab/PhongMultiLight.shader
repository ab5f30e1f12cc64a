// Phong specular with Unity's forward passes: the main directional light in
// ForwardBase, every further pixel light additively in ForwardAdd.
Shader "Examples/PhongMultiLight" {
    Properties {
        _Color ("Diffuse", Color) = (1, 1, 1, 1)
        _SpecColor ("Specular", Color) = (1, 1, 1, 1)
        _Shininess ("Shininess", Range(1, 256)) = 32
    }
    CGINCLUDE
    #include "UnityCG.cginc"
    #include "UnityLightingCommon.cginc"
    #include "AutoLight.cginc"

    fixed4 _Color;
    float _Shininess;

    struct v2f {
        float4 pos : SV_POSITION;
        float3 worldPos : TEXCOORD0;
        float3 worldNormal : TEXCOORD1;
        LIGHTING_COORDS(2, 3)
    };

    v2f vert(appdata_base v) {
        v2f o;
        o.pos = UnityObjectToClipPos(v.vertex);
        o.worldPos = mul(unity_ObjectToWorld, v.vertex).xyz;
        o.worldNormal = UnityObjectToWorldNormal(v.normal);
        TRANSFER_VERTEX_TO_FRAGMENT(o);
        return o;
    }

    fixed3 phong(v2f i) {
        float3 n = normalize(i.worldNormal);
        float3 l = normalize(UnityWorldSpaceLightDir(i.worldPos));
        float3 v = normalize(UnityWorldSpaceViewDir(i.worldPos));
        float3 r = reflect(-l, n);
        float atten = LIGHT_ATTENUATION(i);
        float diffuse = max(0, dot(n, l));
        float specular = pow(max(0, dot(r, v)), _Shininess);
        return atten * _LightColor0.rgb * (_Color.rgb * diffuse + _SpecColor.rgb * specular);
    }
    ENDCG

    SubShader {
        Tags { "RenderType"="Opaque" }
        Pass {
            Name "FORWARD"
            Tags { "LightMode"="ForwardBase" }
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile_fwdbase
            fixed4 frag(v2f i) : SV_Target {
                fixed3 ambient = ShadeSH9(half4(normalize(i.worldNormal), 1)) * _Color.rgb;
                return fixed4(phong(i) + ambient, 1);
            }
            ENDCG
        }
        Pass {
            Name "FORWARD_DELTA"
            Tags { "LightMode"="ForwardAdd" }
            Blend One One
            ZWrite Off
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile_fwdadd
            fixed4 frag(v2f i) : SV_Target {
                return fixed4(phong(i), 1);
            }
            ENDCG
        }
    }
}
