Shader "Test/ForwardLit"
{
    Properties
    {
        _MainTex ("Albedo", 2D) = "white" {}
        _SpecColor ("Specular", Color) = (1, 1, 1, 1)
        _Shininess ("Shininess", Range(0.01, 1)) = 0.5
    }
    CGINCLUDE
    #include "UnityCG.cginc"
    #include "Lighting.cginc"
    #include "AutoLight.cginc"

    sampler2D _MainTex;
    float4 _MainTex_ST;
    float _Shininess;

    struct v2f
    {
        float4 pos : SV_POSITION;
        float2 uv : TEXCOORD0;
        float3 worldNormal : TEXCOORD1;
        float3 worldPos : TEXCOORD2;
        LIGHTING_COORDS(3, 4)
        UNITY_FOG_COORDS(5)
    };

    v2f vert (appdata_base v)
    {
        v2f o;
        UNITY_INITIALIZE_OUTPUT(v2f, o);
        o.pos = UnityObjectToClipPos(v.vertex);
        o.uv = TRANSFORM_TEX(v.texcoord, _MainTex);
        o.worldNormal = UnityObjectToWorldNormal(v.normal);
        o.worldPos = mul(unity_ObjectToWorld, v.vertex).xyz;
        TRANSFER_VERTEX_TO_FRAGMENT(o);
        UNITY_TRANSFER_FOG(o, o.pos);
        return o;
    }

    fixed4 shade (v2f i, float atten)
    {
        SurfaceOutput s;
        UNITY_INITIALIZE_OUTPUT(SurfaceOutput, s);
        s.Albedo = tex2D(_MainTex, i.uv).rgb;
        s.Normal = normalize(i.worldNormal);
        s.Specular = _Shininess;
        s.Gloss = 1;
        s.Alpha = 1;
        UnityGI gi;
        UNITY_INITIALIZE_OUTPUT(UnityGI, gi);
        gi.light.color = _LightColor0.rgb * atten;
        gi.light.dir = normalize(UnityWorldSpaceLightDir(i.worldPos));
        gi.indirect.diffuse = ShadeSH9(float4(s.Normal, 1));
        fixed4 c = LightingBlinnPhong(s, normalize(UnityWorldSpaceViewDir(i.worldPos)), gi);
        UNITY_APPLY_FOG(i.fogCoord, c);
        return c;
    }

    fixed4 frag_base (v2f i) : SV_Target
    {
        UNITY_LIGHT_ATTENUATION(atten, i, i.worldPos);
        return shade(i, atten);
    }

    fixed4 frag_add (v2f i) : SV_Target
    {
        return shade(i, LIGHT_ATTENUATION(i));
    }
    ENDCG

    SubShader
    {
        Pass
        {
            Tags { "LightMode"="ForwardAdd" }
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag_add
            #pragma multi_compile_fwdadd
            #pragma multi_compile_fog
            ENDCG
        }
    }
}
