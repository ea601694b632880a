#version 300 es
// GLSL ES 3.00 before a shader written in 1.00's words (WebGL 2's programs that need 3.00).
#define attribute in
#define varying out
