Shader "Test/Layout"
{
    Properties
    {
        _MainTex ("Albedo", 2D) = "white" {}
        _Cube ("Environment", Cube) = "" {}
        _Color ("Color", Color) = (1, 1, 1, 1)
        _Gloss ("Gloss", Range(0, 1)) = 0.5
        _Unused ("Not in the program", Float) = 0
    }
    SubShader
    {
        Pass
        {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"

            struct Light { float3 direction; float intensity; float4 color; };
            struct Rig { float4x4 bones[2]; Light lights[3]; float2 jitter; };

            cbuffer Scene
            {
                Rig _Rig;
                float3x4 _Affine;
                row_major float2x3 _RowMajor;
                float _Weights[5];
                float2 _Pair;
                int4 _Flags;
            };

            sampler2D _MainTex;
            float4 _MainTex_ST;
            float4 _MainTex_TexelSize;
            half4 _MainTex_HDR;
            samplerCUBE _Cube;
            sampler3D _Volume;
            Texture2DArray _Layers;
            SamplerState sampler_Layers;
            float4 _Color;
            float _Gloss;
            float3 _Tint;
            float _After;

            [[vk::constant_id(7)]] const int kTaps = 4;

            struct PushData { float4 _PushTint; float _PushScale; };
            [[vk::push_constant]] ConstantBuffer<PushData> _Push;

            struct v2f
            {
                float4 pos : SV_POSITION;
                float2 uv : TEXCOORD0;
                float3 normal : NORMAL;
                fixed4 color : COLOR;
                float3x3 tbn : TEXCOORD3;
            };

            v2f vert (appdata_full v)
            {
                v2f o;
                o.pos = UnityObjectToClipPos(v.vertex) + mul(_Rig.bones[1], v.vertex) * _Weights[2];
                o.uv = TRANSFORM_TEX(v.texcoord, _MainTex);
                o.normal = v.normal + mul(_Affine, v.vertex) + _RowMajor[1];
                o.color = v.color;
                o.tbn = float3x3(v.tangent.xyz, v.normal, cross(v.normal, v.tangent.xyz));
                return o;
            }

            fixed4 frag (v2f i) : SV_Target
            {
                float4 c = tex2D(_MainTex, i.uv) * _Color * _Gloss;
                c.rgb *= DecodeHDR(texCUBE(_Cube, i.normal), _MainTex_HDR) + _Tint * _After;
                c += tex3D(_Volume, i.normal) * _MainTex_TexelSize;
                c += _Layers.Sample(sampler_Layers, float3(i.uv, 1));
                for (int k = 0; k < kTaps; ++k) c += _Rig.lights[k % 3].color * _Rig.lights[1].intensity;
                c.xy += _Pair * _Rig.jitter + _Flags.xy;
                c.rgb += mul(i.tbn, i.color.rgb);
                c = c * _Push._PushTint + _Push._PushScale;
                return c;
            }
            ENDCG
        }
    }
}
