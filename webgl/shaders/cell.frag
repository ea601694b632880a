varying float v_val;
void main() {
  gl_FragColor = vec4(colour(v_val), 1.0);
}
