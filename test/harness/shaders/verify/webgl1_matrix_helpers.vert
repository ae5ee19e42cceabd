// A WebGL1 vertex shader (no #version, no precision statement) that writes the matrix helpers
// ESSL 100 lacks itself and builds a normal matrix from the model-view matrix.
attribute vec3 position;
attribute vec3 normal;
uniform mat4 modelViewMatrix;
uniform mat4 projectionMatrix;
varying vec3 vNormal;

mat3 transpose(mat3 m)
{
    return mat3(m[0].x, m[1].x, m[2].x,
                m[0].y, m[1].y, m[2].y,
                m[0].z, m[1].z, m[2].z);
}

void main()
{
    vNormal = normalize(transpose(mat3(modelViewMatrix)) * normal);
    gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);
}
