precision mediump float;
// The colour of a value, shared by the edges and the cells (prepended to their fragment
// shaders). t = clamp(value / scale, 0, 1); strain: red = base + (1 - base) * t, so brightness
// grows linearly with the strain and an unstrained edge stays visible; stress: blue to red.
uniform float u_mode;      // 0 strain, 1 stress
uniform float u_invScale;
uniform float u_base;
vec3 colour(float value) {
  float t = clamp(value * u_invScale, 0.0, 1.0);
  return u_mode < 0.5 ? vec3(u_base + (1.0 - u_base) * t, 0.0, 0.0)
                      : mix(vec3(0.0, 0.0, 1.0), vec3(1.0, 0.0, 0.0), t);
}
