Shader "Test/CgIncludeError"
{
    CGINCLUDE
    #include "UnityCG.cginc"
    float4 Helper(float4 x)
    {
        return x * missingScale;
    }
    ENDCG

    SubShader
    {
        Pass
        {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            float4 vert (float4 v : POSITION) : SV_POSITION { return UnityObjectToClipPos(v); }
            fixed4 frag () : SV_Target { return Helper(1); }
            ENDCG
        }
    }
}
