#version 110
// Fixed-function lighting state of the compatibility profile (gl_LightSource, gl_FrontMaterial,
// gl_LightModel): the translation the analysis reads declares it as uniform structs of its own,
// the members the specification lists; the same-language output keeps the shader's text (the
// driver's state), another language's output declares the structs. Before, refused. Checked by
// execution in Mesa in test/harness/piglit/gl110-fixed-function-light-state.shader_test.
// RUN: %stereoshift %s -o %t.vert
// RUN: FileCheck %s < %t.vert
// RUN: %stereoshift %s --target glsl --target-version 330 -o - | FileCheck %s --check-prefix=GL330
// CHECK: {{^}}    gl_FrontColor = gl_FrontMaterial.emission + gl_LightSource[0].diffuse * gl_Color * d;
// CHECK: gl_Position.x = gl_Position.x + (eyeSign * separation) * (gl_Position.w - convergence);
// GL330: struct stereoshift_LightSourceParameters
// GL330: vec4 diffuse;
// GL330: struct stereoshift_MaterialParameters
// GL330: uniform stereoshift_LightSourceParameters stereoshift_LightSource[8];
//
// The compatibility inputs of a geometry stage (gl_TexCoordIn, gl_FrontColorIn) are not
// translated: a located error, non-zero exit, no output.
// RUN: printf '%%s\n' '#version 150 compatibility' 'layout(triangles) in;' 'layout(triangle_strip, max_vertices = 3) out;' 'void main() { for (int i = 0; i < 3; ++i) { gl_TexCoord[0] = gl_TexCoordIn[i][0]; gl_Position = gl_in[i].gl_Position; EmitVertex(); } }' > %t.geom
// RUN: %not %stereoshift %t.geom -o %t.out.geom 2>&1 | FileCheck %s --check-prefix=GEOM
// RUN: test ! -e %t.out.geom
// GEOM: error: 'gl_TexCoordIn' is a compatibility-profile input of the geometry stage that stereoshift cannot translate
void main() {
    vec3 n = normalize(gl_NormalMatrix * gl_Normal);
    float d = max(dot(n, normalize(gl_LightSource[0].position.xyz)), 0.0);
    gl_Position = ftransform();
    gl_FrontColor = gl_FrontMaterial.emission + gl_LightSource[0].diffuse * gl_Color * d;
}
