struct O { RWStructuredBuffer<float4> b; };
float4 vert(O o) : SV_Position { return 0; }
float4 frag() : SV_Target { return 1; }
