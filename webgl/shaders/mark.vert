attribute vec2 a_corner;   // -1..1 square
attribute vec2 a_center;   // world metres
attribute float a_kind;    // 0 pinned, 1 held, 2 held and pinned
uniform vec2 u_scale;
uniform vec2 u_offset;
uniform vec2 u_viewport;
uniform float u_pinRadius;
uniform float u_heldRadius;
varying vec2 v_uv;
varying float v_kind;
varying float v_radius;
void main() {
  float r = (a_kind > 0.5 ? u_heldRadius : u_pinRadius) + 1.0;
  vec2 p = a_center * u_scale + u_offset + a_corner * r;
  v_uv = a_corner * r;
  v_kind = a_kind;
  v_radius = r - 1.0;
  vec2 clip = p / u_viewport * 2.0 - 1.0;
  gl_Position = vec4(clip.x, -clip.y, 0.0, 1.0);
}
