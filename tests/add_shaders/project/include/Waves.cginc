float _Amplitude;
float4 wave(float4 p) { return p + float4(0, sin(p.x) * _Amplitude, 0, 0); }
