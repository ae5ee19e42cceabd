#version 110
// stereoshift-expect: fragment
// GL 2.x tutorial per-pixel Phong fragment shader: lighting uniforms of its own, gl_FragColor.
uniform vec3 lightPosition;
uniform vec4 diffuseColor;
uniform vec4 specularColor;
uniform float shininess;

varying vec3 normal;
varying vec3 eyePosition;

void main()
{
    vec3 n = normalize(normal);
    vec3 l = normalize(lightPosition - eyePosition);
    vec3 v = normalize(-eyePosition);
    vec3 h = normalize(l + v);
    float diffuse = max(dot(n, l), 0.0);
    float specular = pow(max(dot(n, h), 0.0), shininess);
    gl_FragColor = diffuseColor * diffuse + specularColor * specular;
}
