precision mediump float;
uniform float u_px;        // device pixels per CSS pixel
varying vec2 v_uv;
varying float v_kind;
varying float v_radius;
void main() {
  float d = length(v_uv);
  float outer = clamp(v_radius + 0.5 - d, 0.0, 1.0);
  vec4 c;
  if (v_kind < 0.5) {
    // pinned: a light disc with a dark outline
    float inner = clamp(v_radius - 1.5 * u_px + 0.5 - d, 0.0, 1.0);
    c = mix(vec4(0.05, 0.06, 0.08, 1.0), vec4(0.92, 0.94, 0.97, 1.0), inner) * outer;
  } else {
    // held: an amber ring (filled centre when also pinned)
    float ring = clamp(v_radius - 2.0 * u_px + 0.5 - d, 0.0, 1.0);
    float fill = v_kind > 1.5 ? 1.0 : 1.0 - ring;
    c = vec4(1.0, 0.75, 0.2, 1.0) * outer * fill;
  }
  gl_FragColor = c;
}
