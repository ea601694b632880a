precision mediump float;
uniform float u_mode;      // 0 strain, 1 stress
uniform float u_invScale;
uniform float u_halfWidth;
uniform float u_base;
varying float v_val;
varying float v_side;
void main() {
  float t = clamp(v_val * u_invScale, 0.0, 1.0);
  vec3 c = u_mode < 0.5 ? vec3(u_base + (1.0 - u_base) * t, 0.0, 0.0)
                        : mix(vec3(0.0, 0.0, 1.0), vec3(1.0, 0.0, 0.0), t);
  float a = clamp(u_halfWidth + 0.5 - abs(v_side), 0.0, 1.0);
  gl_FragColor = vec4(c * a, a);  // premultiplied alpha
}
