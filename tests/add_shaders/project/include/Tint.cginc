float4 _Tint;
float4 tint(float4 c) { return c * _Tint; }
