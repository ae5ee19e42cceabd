#version 330
// per-eye-view where the camera is a member of a loose struct uniform the shader copies whole into
// a local (`Frame f = frame;`) and reads through the copy: in the spliced text the copy goes
// through stereoshift_holder_frame, which returns the struct with this eye's camera (the member
// through stereoshift_eye_frame_cameraPosition); the matrices in the copy stay the mono ones. Undoing the
// marked edits gives the input back; --verify runs it against the exact stereo reference.
// RUN: %stereoshift --validate-each --verify %s -o %t.vert --report %t.json 2>&1 | FileCheck %s --check-prefix=NOTE --allow-empty
// RUN: %rmchecks %t.vert | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
// RUN: %rmchecks %s > %t.in.vert && %rmchecks %t.vert > %t.out.vert
// RUN: %python -c "import sys; sys.path.insert(0, sys.argv[1]); import check_corpus as c; sys.exit(0 if c.only_marked_edits(open(sys.argv[2]).read(), open(sys.argv[3]).read()) else 1)" %S/../../corpus %t.in.vert %t.out.vert
// NOTE-NOT: re-emitted
// CHECK:      {{^}}/* ---- stereoshift ---- */ Frame stereoshift_holder_frame(Frame stereoshift_holder); /* ---- end stereoshift ---- */ void main_stereoshift_mono()
// CHECK:      Frame f = stereoshift_holder_frame(frame);
// CHECK:      vec3 stereoshift_eye_frame_cameraPosition(vec3 stereoshift_camera)
// CHECK:      Frame stereoshift_holder_frame(Frame stereoshift_holder)
// CHECK-NEXT: {
// CHECK-NEXT:     stereoshift_holder.cameraPosition = stereoshift_eye_frame_cameraPosition(stereoshift_holder.cameraPosition);
// CHECK-NEXT:     return stereoshift_holder;
// CHECK-NEXT: }
// REPORT: "route": "glsl-source-splice"
// REPORT: "verified": true
struct Frame
{
    mat4 viewProj;
    vec3 cameraPosition;
    float time;
};
uniform Frame frame;
uniform mat4 uModel;
in vec3 aPosition;
in vec3 aNormal;
in vec4 aTangent;
out vec3 vTangentView;

void main()
{
    Frame f = frame;
    vec4 world = uModel * vec4(aPosition, 1.0);
    vec3 n = normalize(mat3(uModel) * aNormal);
    vec3 t = normalize(mat3(uModel) * aTangent.xyz);
    mat3 tbn = transpose(mat3(t, cross(n, t) * aTangent.w, n));
    vTangentView = tbn * (f.cameraPosition - world.xyz);
    gl_Position = f.viewProj * world;
}
