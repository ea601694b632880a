// An edge's quad, shared by both edge programs (prepended to their vertex shaders): the
// corner (x: 0 at end a, 1 at end b; y: side, -1 or +1) of a quad stretched over the edge from
// pa to pb (world metres), in device pixels, so lines have the same width at any size and
// devicePixelRatio (gl.lineWidth > 1 is ignored by most implementations).
uniform vec2 u_scale;      // world metres -> device pixels (y flips)
uniform vec2 u_offset;
uniform vec2 u_viewport;   // device pixels
uniform mediump float u_halfWidth; // device pixels (precision shared with the fragment shader)
varying float v_val;
varying float v_side;
void place(vec2 corner, vec2 worldA, vec2 worldB, vec2 val) {
  vec2 pa = worldA * u_scale + u_offset;
  vec2 pb = worldB * u_scale + u_offset;
  vec2 d = pb - pa;
  float len = length(d);
  vec2 dir = len > 1e-6 ? d / len : vec2(1.0, 0.0);
  vec2 nrm = vec2(-dir.y, dir.x);
  float reach = u_halfWidth + 1.0;  // one extra pixel for the antialiased rim
  vec2 p = mix(pa, pb, corner.x) + dir * (2.0 * corner.x - 1.0) * u_halfWidth
         + nrm * corner.y * reach;
  v_val = mix(val.x, val.y, corner.x);
  v_side = corner.y * reach;
  vec2 clip = p / u_viewport * 2.0 - 1.0;
  gl_Position = vec4(clip.x, -clip.y, 0.0, 1.0);
}
