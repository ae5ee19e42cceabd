#version 450
void main() {
  gl_Position = vec4(1.0, 2.0, 3.0, 4.0);
}
