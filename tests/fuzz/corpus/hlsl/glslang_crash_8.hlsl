#define COUNT 4
static const float weights[COUN\] = { 0.1, 0.2, 0.3, 0.4 };
sa.pos = float4(o.uv k* 2 - 1, 0, 1);
  retr onu111111111111111111111111111111