// facet's terrain painting helpers (Unity's TerrainTool.cginc names, 2018.3+):
// mapping a paint-context uv into the brush texture.
#ifndef TERRAIN_TOOL_INCLUDED
#define TERRAIN_TOOL_INCLUDED

// Set by the painting tool (loose globals, filled by name): the brush uv is
// an affine function of the paint-context uv.
float4 _PCUVToBrushUVScales;   // xy = d(brush uv)/d(pc u), zw = d(brush uv)/d(pc v)
float2 _PCUVToBrushUVOffset;

float2 PaintContextUVToBrushUV(float2 pcUV)
{
    return _PCUVToBrushUVScales.xy * pcUV.x + _PCUVToBrushUVScales.zw * pcUV.y + _PCUVToBrushUVOffset;
}

// The paint context covers the heightmap texel for texel.
float2 PaintContextUVToHeightmapUV(float2 pcUV)
{
    return pcUV;
}

#endif // TERRAIN_TOOL_INCLUDED
