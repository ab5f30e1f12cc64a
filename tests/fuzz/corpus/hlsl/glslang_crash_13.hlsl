struct S { float a; };
half _G S;
float4 vert(float4 p : POSITION) : SV_Position { return p; }
float4 frag() : SV_Target { return 0; }
