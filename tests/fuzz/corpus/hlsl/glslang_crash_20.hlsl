struct CompFrontBlendS { float a; }v;
half _G S;
float4 vert(float4 pFailFront : POSITION) : S,V_Position
half _G S;
float4 vert(float4 pFailFront : POSITION) : S,V_Position { return p; }
float2 frag()GL_GOOGLE_cpp_style_line_d : SV_Target { return p; }
float2 frag()GL_GOOGLE_cpp_style_line_d : SV_Target { NNNNNNNN^NNNNNNNNNNNNNNNNNNNNNNNNNNNNNNNNNNNNNNNNNNNNNNNNNNNNNNNNNNNNNNNN;NNNNNNNNNNNNNNNNNNNNNNNNNNNNNNreturn 0; }
