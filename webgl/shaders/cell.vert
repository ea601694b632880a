attribute vec2 a_pos;      // a vertex, world metres
attribute float a_val;     // its colour value
uniform vec2 u_scale;      // world metres -> device pixels (y flips)
uniform vec2 u_offset;
uniform vec2 u_viewport;   // device pixels
varying float v_val;
void main() {
  vec2 p = a_pos * u_scale + u_offset;
  v_val = a_val;
  vec2 clip = p / u_viewport * 2.0 - 1.0;
  gl_Position = vec4(clip.x, -clip.y, 0.0, 1.0);
}
