// Every render-state command, in canonical and odd spellings.
shader "Tests/AllState" {
  properties {
    [KeywordEnum(None, Add Light, Multiply)] _Overlay ("Overlay", Float) = 0
    [Enum(UnityEngine.Rendering.BlendMode)] _SrcBlend ("Src", Float) = 1
    [Enum(UnityEngine.Rendering.CompareFunction)] _StencilComp ("Stencil Comparison", Int) = 8
    [Toggle(_FANCY_ON)] _Fancy ("Fancy", Float) = 0
    [PowerSlider(3.0)] _Shininess ("Shininess", Range (0.01, 1)) = 0.08
    [IntRange] _Steps ("Steps", Range(1, 16)) = 4
    [Header(Surface Options)] [Space] [Space(20)] _Cutoff ("Cutoff", Range(0,1)) = 0.5
    [NoScaleOffset] [Normal] _BumpMap ("Normal", 2D) = "bump" { TexGen CubeReflect }
    [HDR] _Emission ("Emission", Color) = (0,0,0,1)
    [MyCustomDrawer(a, b)] _Vec ("Vector", Vector) = (1, 2, 3, 4)
    _Count ("Count", Integer) = -3
    _Legacy ("Legacy int", Int) = 2
    _Volume ("Volume", 3D) = "" {}
    _Layers ("Layers", 2DArray) = "black" {}
    _Probes ("Probes", CubeArray) = "gray" {}
    _Lin ("Lin", 2D) = "linearGray" {}
  }
  SUBSHADER {
    cull back
    ztest lequal
    blend srcalpha oneminussrcalpha
    Pass {
      Cull Front
      ZTest [_ZTest]
      ZWrite off
      Blend Off
      Blend 1 One Zero, SrcAlpha OneMinusDstAlpha
      BlendOp RevSub, Max
      BlendOp 2 Add
      ColorMask rgb
      ColorMask 0 1
      ColorMask [_Mask] 2
      Offset -1, -1
      AlphaToMask On
      ZClip False
      Conservative True
      Stencil {
        Ref [_StencilRef] ReadMask 255 WriteMask 15
        Comp [_StencilComp] Pass Replace Fail Keep ZFail IncrWrap
        CompBack Less PassBack IncrSat FailBack DecrSat ZFailBack Invert
        CompFront Greater PassFront DecrWrap FailFront Zero ZFailFront Keep
      }
      HLSLPROGRAM
      #pragma vertex vert
      #pragma fragment frag
      ENDHLSL
    }
  }
}
