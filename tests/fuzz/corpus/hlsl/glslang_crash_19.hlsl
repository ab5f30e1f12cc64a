#define COUNT 4
static const float weightGL_EXT_shader_atomic_floatt float weights[C&OUNT]_Textube3D _MainTex;
Sampler
cbuffLODer Ma
Saiai