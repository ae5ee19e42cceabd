#version 330 core
// stereoshift-expect: fragment
// LearnOpenGL-style Phong fragment shader: the camera position only feeds specular, so it stays mono.
out vec4 FragColor;

in vec3 Normal;
in vec3 FragPos;

uniform vec3 lightPos;
uniform vec3 viewPos;
uniform vec3 lightColor;
uniform vec3 objectColor;

void main()
{
    vec3 norm = normalize(Normal);
    vec3 lightDir = normalize(lightPos - FragPos);
    float diff = max(dot(norm, lightDir), 0.0);
    vec3 viewDir = normalize(viewPos - FragPos);
    vec3 reflectDir = reflect(-lightDir, norm);
    float spec = pow(max(dot(viewDir, reflectDir), 0.0), 32.0);
    vec3 result = (0.1 + diff + 0.5 * spec) * lightColor * objectColor;
    FragColor = vec4(result, 1.0);
}
