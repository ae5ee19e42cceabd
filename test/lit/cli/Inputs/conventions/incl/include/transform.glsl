vec4 toClip(mat4 mvp, vec3 p) { return mvp * vec4(p, 1.0); }
