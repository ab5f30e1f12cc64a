// Unity's built-in shader variables: the uniforms of FacetBuiltins.hlsl plus
// the UNITY_MATRIX_* names. Included implicitly by CGPROGRAM.
#ifndef UNITY_SHADER_VARIABLES_INCLUDED
#define UNITY_SHADER_VARIABLES_INCLUDED

#include "HLSLSupport.cginc"
#include "FacetBuiltins.hlsl"

#define UNITY_MATRIX_M unity_ObjectToWorld
#define UNITY_MATRIX_I_M unity_WorldToObject
#define UNITY_MATRIX_V unity_MatrixV
#define UNITY_MATRIX_I_V unity_MatrixInvV
#define UNITY_MATRIX_P unity_MatrixP
#define UNITY_MATRIX_VP unity_MatrixVP
#define UNITY_MATRIX_MV mul(unity_MatrixV, unity_ObjectToWorld)
#define UNITY_MATRIX_T_MV transpose(UNITY_MATRIX_MV)
#define UNITY_MATRIX_IT_MV transpose(mul(unity_WorldToObject, unity_MatrixInvV))
#define UNITY_MATRIX_MVP mul(unity_MatrixVP, unity_ObjectToWorld)
#define glstate_matrix_projection unity_MatrixP
#define UNITY_LIGHTMODEL_AMBIENT glstate_lightmodel_ambient

#include "UnityInstancing.cginc"

#endif // UNITY_SHADER_VARIABLES_INCLUDED
