attribute vec2 a_corner;   // x: 0 at end a, 1 at end b; y: side, -1 or +1
attribute vec2 a_pa;
attribute vec2 a_pb;
attribute vec2 a_val;      // colour value at end a and end b
uniform vec2 u_scale;      // world metres -> device pixels (y flips)
uniform vec2 u_offset;
uniform vec2 u_viewport;   // device pixels
uniform mediump float u_halfWidth; // device pixels (precision shared with the fragment shader)
varying float v_val;
varying float v_side;
void main() {
  vec2 pa = a_pa * u_scale + u_offset;
  vec2 pb = a_pb * u_scale + u_offset;
  vec2 d = pb - pa;
  float len = length(d);
  vec2 dir = len > 1e-6 ? d / len : vec2(1.0, 0.0);
  vec2 nrm = vec2(-dir.y, dir.x);
  float reach = u_halfWidth + 1.0;  // one extra pixel for the antialiased rim
  vec2 p = mix(pa, pb, a_corner.x) + dir * (2.0 * a_corner.x - 1.0) * u_halfWidth
         + nrm * a_corner.y * reach;
  v_val = mix(a_val.x, a_val.y, a_corner.x);
  v_side = a_corner.y * reach;
  vec2 clip = p / u_viewport * 2.0 - 1.0;
  gl_Position = vec4(clip.x, -clip.y, 0.0, 1.0);
}
