Shader "Test/MissingEntry"
{
    SubShader
    {
        Pass
        {
            CGPROGRAM
            #pragma vertex vertex_main
            #pragma fragment frag
            float4 vert (float4 v : POSITION) : SV_POSITION { return v; }
            fixed4 frag () : SV_Target { return 1; }
            ENDCG
        }
    }
}
