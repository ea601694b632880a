// WebGL 2: no instancing. Six vertices an edge (two triangles), each finding its edge and
// corner from gl_VertexID and the edge's data in a texture, three RG32F texels an edge:
// (ax, ay), (bx, by), (va, vb), u_perRow edges a row. A software rasteriser (SwiftShader)
// pays per instance: the instanced draw of a 40x30 curtain's 4,592 edges took it 70 ms of CPU.
uniform highp sampler2D u_edges;
uniform int u_perRow;
const vec2 CORNERS[6] = vec2[6](vec2(0.0, -1.0), vec2(0.0, 1.0), vec2(1.0, -1.0),
                                vec2(1.0, -1.0), vec2(0.0, 1.0), vec2(1.0, 1.0));
void main() {
  int e = gl_VertexID / 6;
  int row = e / u_perRow;
  int col = 3 * (e - row * u_perRow);
  place(CORNERS[gl_VertexID - 6 * e],
        texelFetch(u_edges, ivec2(col, row), 0).xy,
        texelFetch(u_edges, ivec2(col + 1, row), 0).xy,
        texelFetch(u_edges, ivec2(col + 2, row), 0).xy);
}
