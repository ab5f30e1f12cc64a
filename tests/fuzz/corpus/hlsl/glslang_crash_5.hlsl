#define COUNT 4
static const float weights[CO#include "UnityCG.UNT] = { 0.1, 0.2, 0cginc"
#.