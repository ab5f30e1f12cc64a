// facet's terrain brush-preview helpers (Unity's TerrainPreview.cginc names,
// 2018.3+): affine maps from paint-context pixels to heightmap uv, terrain
// object position and brush uv, and a procedural grid mesh for
// DrawProcedural (which sets no object matrices).
#ifndef TERRAIN_PREVIEW_INCLUDED
#define TERRAIN_PREVIEW_INCLUDED

// All set by the terrain tools (loose globals, filled by name).
sampler2D _Heightmap;

float2 _HeightmapUV_PCPixelsX, _HeightmapUV_PCPixelsY, _HeightmapUV_Offset;
float2 PaintContextPixelsToHeightmapUV(float2 pcPixels)
{
    return _HeightmapUV_PCPixelsX * pcPixels.x + _HeightmapUV_PCPixelsY * pcPixels.y + _HeightmapUV_Offset;
}

float3 _ObjectPos_PCPixelsX, _ObjectPos_PCPixelsY, _ObjectPos_HeightMapSample, _ObjectPos_Offset;
float3 PaintContextPixelsToObjectPosition(float2 pcPixels, float heightmapSample)
{
    return _ObjectPos_PCPixelsX * pcPixels.x + _ObjectPos_PCPixelsY * pcPixels.y
         + _ObjectPos_HeightMapSample * heightmapSample + _ObjectPos_Offset;
}

float2 _BrushUV_PCPixelsX, _BrushUV_PCPixelsY, _BrushUV_Offset;
float2 PaintContextPixelsToBrushUV(float2 pcPixels)
{
    return _BrushUV_PCPixelsX * pcPixels.x + _BrushUV_PCPixelsY * pcPixels.y + _BrushUV_Offset;
}

// Terrains are never rotated or scaled, so object -> world is a translation.
float3 _TerrainObjectToWorldOffset;
float3 TerrainObjectToWorldPosition(float3 objectPosition)
{
    return objectPosition + _TerrainObjectToWorldOffset;
}

// Grid vertex of a procedural mesh of _QuadRez.x by _QuadRez.y quads, six
// vertices (two triangles) per quad, row by row: returns the integer grid
// position times the vertex skip (_QuadRez.w; 2018-2019 engines set only
// xyz, so 0 there means 1).
float4 _QuadRez;   // quads x, quads y, vertex count, vertex skip
float2 BuildProceduralQuadMeshVertex(uint vertexID)
{
    int quad = int(vertexID / 6);
    int corner = int(vertexID) - quad * 6;            // 0..5
    int qy = int(floor((quad + 0.5f) / _QuadRez.x));
    int qx = int(round(quad - qy * _QuadRez.x));
    // corners (x, y): (0,0) (0,1) (1,1) (1,1) (1,0) (0,0)
    float vx = (corner >= 2 && corner <= 4) ? 1.0f : 0.0f;
    float vy = (corner >= 1 && corner <= 3) ? 1.0f : 0.0f;
    float skip = _QuadRez.w > 0.0f ? _QuadRez.w : 1.0f;
    return float2(qx + vx, qy + vy) * skip;
}

// Anti-aliased stripe of pixelWidth pixels centred at x = stripeX: the
// distance to the stripe in pixels comes from the screen-space derivatives.
float Stripe(in float x, in float stripeX, in float pixelWidth)
{
    float perPixel = 1.0f / max(length(float2(ddx(x), ddy(x))), 0.00001f);
    return saturate(0.5f + 0.5f * (0.5f * pixelWidth - perPixel * abs(x - stripeX)));
}

#endif // TERRAIN_PREVIEW_INCLUDED
