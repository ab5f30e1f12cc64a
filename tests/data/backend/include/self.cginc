// Includes itself without a guard.
#include "self.cginc"
float4 _SelfValue;
