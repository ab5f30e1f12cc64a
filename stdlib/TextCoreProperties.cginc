// TextCore's material properties under their older file name
// (Unity 2019.4 / 6000 TextCore-SDF): see TextCore_Properties.cginc.
#include "TextCore_Properties.cginc"
