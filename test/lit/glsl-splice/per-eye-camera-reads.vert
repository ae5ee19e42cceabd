// per-eye-view in the shader's own text: every read of the camera in a function body, a helper's
// included, goes through stereoshift_eye_<camera>(), whose prototype sits before each function that
// reads it and whose definition (the camera plus this eye's offset, from the inverse of the matrices
// that take the same world point to the clip position) is in the appended block; the camera's own
// declaration and a member of another struct with its name stay as written. Undoing the marked
// edits gives the input back, and the output compiles.
// RUN: %stereoshift --validate-each --verify %s -o %t.vert --report %t.json
// RUN: %rmchecks %t.vert | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
// RUN: glslangValidator -S vert %t.vert
// RUN: %rmchecks %s > %t.in.vert && %rmchecks %t.vert > %t.out.vert
// RUN: %python -c "import sys; sys.path.insert(0, sys.argv[1]); import check_corpus as c; sys.exit(0 if c.only_marked_edits(open(sys.argv[2]).read(), open(sys.argv[3]).read()) else 1)" %S/../../corpus %t.in.vert %t.out.vert
// CHECK:      {{^}}uniform vec3 uEyePos;
// CHECK:      {{^}}/* ---- stereoshift ---- */ vec3 stereoshift_eye_uEyePos(vec3 stereoshift_camera); /* ---- end stereoshift ---- */ vec3 toEye(vec3 p)
// CHECK-NEXT: {
// CHECK-NEXT:     return stereoshift_eye_uEyePos(uEyePos) - p + probe.uEyePos * 0.0;
// CHECK:      {{^}}/* ---- stereoshift ---- */ vec3 stereoshift_eye_uEyePos(vec3 stereoshift_camera); /* ---- end stereoshift ---- */ void main_stereoshift_mono()
// CHECK:      vView = tbn * toEye(world.xyz);
// CHECK-NEXT: vEyeHeight = stereoshift_eye_uEyePos(uEyePos).y;
// CHECK:      vec3 stereoshift_eye_uEyePos(vec3 stereoshift_camera)
// CHECK-NEXT: {
// CHECK-NEXT:     return stereoshift_camera + (inverse(uViewProj) * vec4((eyeSign * separation) * convergence, 0.0, 0.0, 0.0)).xyz;
// CHECK-NEXT: }
// REPORT: "uniform": "uEyePos",
// REPORT: "route": "glsl-source-splice"
#version 330
struct Probe { vec3 uEyePos; float weight; };
uniform Probe probe;
uniform mat4 uModel;
uniform mat4 uViewProj;
uniform vec3 uEyePos;
in vec3 aPosition;
in vec3 aNormal;
in vec4 aTangent;
out vec3 vView;
out float vEyeHeight;

vec3 toEye(vec3 p)
{
    return uEyePos - p + probe.uEyePos * 0.0;
}

void main()
{
    vec4 world = uModel * vec4(aPosition, 1.0);
    vec3 n = normalize(mat3(uModel) * aNormal);
    vec3 t = normalize(mat3(uModel) * aTangent.xyz);
    mat3 tbn = transpose(mat3(t, cross(n, t) * aTangent.w, n));
    vView = tbn * toEye(world.xyz);
    vEyeHeight = uEyePos.y;
    gl_Position = uViewProj * world;
}
