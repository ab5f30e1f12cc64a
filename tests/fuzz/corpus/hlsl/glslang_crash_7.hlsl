#define COUNT 4
static const float weights[COUN\] = { 0.1, 0.1, 0.3, 0.4 };
sa.pos = float4(o.uv * GL_EXT_shader_subgroup_extended_types_int16i) : SV_Target {
  half4 su5, sumNT 4
staticurn sum;
}
