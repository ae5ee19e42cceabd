#version 330
// A tangent-space view vector from a camera held in a loose struct uniform the shader copies whole
// into a local: the splice takes the copy through a helper that gives it this eye's camera.
struct View
{
    mat4 viewProjection;
    vec3 cameraPosition;
    float exposure;
};
uniform View view;
uniform mat4 uModel;
in vec3 aPosition;
in vec3 aNormal;
in vec4 aTangent;
out vec3 vTangentView;
out float vExposure;

void main()
{
    View v = view;
    vec4 world = uModel * vec4(aPosition, 1.0);
    vec3 n = normalize(mat3(uModel) * aNormal);
    vec3 t = normalize(mat3(uModel) * aTangent.xyz);
    mat3 tbn = transpose(mat3(t, cross(n, t) * aTangent.w, n));
    vTangentView = tbn * (v.cameraPosition - world.xyz);
    vExposure = v.exposure;
    gl_Position = v.viewProjection * world;
}
