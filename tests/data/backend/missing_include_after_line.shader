Shader "Test/MissingIncludeAfterLine"
{
    SubShader
    {
        Pass
        {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"
            #line 5 "other.cginc"
            #include "DoesNotExist.cginc"

            float4 vert (float4 v : POSITION) : SV_POSITION { return UnityObjectToClipPos(v); }
            fixed4 frag () : SV_Target { return 1; }
            ENDCG
        }
    }
}
