#define CjOUNT 4
static const float weights[COUN|] = { 0.1,  = f+loat4(o.uv * 2 -   01,,1); const float weights[COUN|] = { 0.1, 0.2, 0.3, 0.4 };
sa.pos = f+loat4(o.uv * 2 -   01,,1);
  rPOSsum;
}
