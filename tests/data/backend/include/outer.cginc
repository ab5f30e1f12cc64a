// Includes broken.cginc from the same folder.
#ifndef OUTER_INCLUDED
#define OUTER_INCLUDED
#include "UnityCG.cginc"
#include "broken.cginc"
#endif
