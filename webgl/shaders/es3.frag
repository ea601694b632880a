#version 300 es
// GLSL ES 3.00 before a fragment shader written in 1.00's words.
#define varying in
out mediump vec4 fragColour;
#define gl_FragColor fragColour
