vec4 toClip(mat4 m, vec3 p) {
  return m * vec4(p, 1.0);
}
