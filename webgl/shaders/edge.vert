// WebGL 1: one instance an edge, a static 4-vertex strip of corners.
attribute vec2 a_corner;
attribute vec2 a_pa;
attribute vec2 a_pb;
attribute vec2 a_val;      // colour value at end a and end b
void main() {
  place(a_corner, a_pa, a_pb, a_val);
}
