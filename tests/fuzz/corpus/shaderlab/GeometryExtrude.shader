// Vertex + geometry + fragment: every triangle is pushed out along its face
// normal by _Extrude and drawn together with its three side walls, so the
// mesh looks like a set of raised tiles. The geometry stage sees the whole
// triangle (the `triangle` input) and appends up to 15 vertices (one cap of
// 3 and three walls of 4) to a TriangleStream.
Shader "Examples/GeometryExtrude" {
    Properties {
        _Color ("Color", Color) = (0.8, 0.6, 0.3, 1)
        _WallColor ("Wall Color", Color) = (0.3, 0.2, 0.1, 1)
        _Extrude ("Extrusion", Range(0, 0.5)) = 0.1
    }
    SubShader {
        Tags { "RenderType"="Opaque" "Queue"="Geometry" }
        Pass {
            Tags { "LightMode"="ForwardBase" }
            Cull Back
            CGPROGRAM
            #pragma vertex vert
            #pragma geometry geom
            #pragma fragment frag
            #pragma target 4.0
            #pragma multi_compile_fog
            #include "UnityCG.cginc"

            fixed4 _Color, _WallColor;
            float _Extrude;

            struct v2g {
                float4 worldPos : TEXCOORD0;
            };

            struct g2f {
                float4 pos : SV_POSITION;
                float3 worldNormal : TEXCOORD0;
                fixed4 color : COLOR0;
                UNITY_FOG_COORDS(1)
            };

            v2g vert(appdata_base v) {
                v2g o;
                o.worldPos = mul(unity_ObjectToWorld, v.vertex);
                return o;
            }

            g2f corner(float3 worldPos, float3 worldNormal, fixed4 color) {
                g2f o;
                o.pos = mul(UNITY_MATRIX_VP, float4(worldPos, 1.0));
                o.worldNormal = worldNormal;
                o.color = color;
                UNITY_TRANSFER_FOG(o, o.pos);
                return o;
            }

            [maxvertexcount(15)]
            void geom(triangle v2g IN[3], uint primitive : SV_PrimitiveID, inout TriangleStream<g2f> stream) {
                float3 p0 = IN[0].worldPos.xyz, p1 = IN[1].worldPos.xyz, p2 = IN[2].worldPos.xyz;
                float3 n = normalize(cross(p1 - p0, p2 - p0));
                float3 offset = n * _Extrude;
                // The raised cap.
                stream.Append(corner(p0 + offset, n, _Color));
                stream.Append(corner(p1 + offset, n, _Color));
                stream.Append(corner(p2 + offset, n, _Color));
                stream.RestartStrip();
                // A wall along each edge, from the base up to the cap; alternate
                // walls are shaded a little differently by primitive id.
                float3 base[3] = { p0, p1, p2 };
                fixed4 wall = _WallColor * ((primitive & 1) ? 0.9 : 1.0);
                for (int i = 0; i < 3; ++i) {
                    float3 a = base[i], b = base[(i + 1) % 3];
                    float3 side = normalize(cross(b - a, n));
                    stream.Append(corner(a, side, wall));
                    stream.Append(corner(b, side, wall));
                    stream.Append(corner(a + offset, side, wall));
                    stream.Append(corner(b + offset, side, wall));
                    stream.RestartStrip();
                }
            }

            fixed4 frag(g2f i) : SV_Target {
                float3 lightDir = normalize(_WorldSpaceLightPos0.xyz);
                fixed4 c = i.color;
                c.rgb *= 0.3 + 0.7 * saturate(dot(normalize(i.worldNormal), lightDir));
                UNITY_APPLY_FOG(i.fogCoord, c);
                return c;
            }
            ENDCG
        }
    }
}
