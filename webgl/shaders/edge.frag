uniform float u_halfWidth;
varying float v_val;
varying float v_side;
void main() {
  float a = clamp(u_halfWidth + 0.5 - abs(v_side), 0.0, 1.0);
  gl_FragColor = vec4(colour(v_val) * a, a);  // premultiplied alpha
}
