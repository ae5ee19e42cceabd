#version 300 es

invariant gl_Position;

uniform mat4 uModel;
uniform vec4 uWave;
uniform float uTime;
uniform mat4 uViewProj;
uniform float eyeSign;
uniform float separation;
uniform float convergence;

layout(location = 0) in vec3 aPosition;
out mediump vec3 vNormal;
out mediump vec2 vTexCoord;
layout(location = 1) in vec2 aTexCoord;
out vec4 vClipPos;
out vec2 vScreenUV;

void main()
{
    vec4 world = uModel * vec4(aPosition, 1.0);
    float k = 6.283185482025146484375 / uWave.w;
    float phase = (k * dot(uWave.xy, world.xz)) - (uTime * 1.5);
    world.y += (uWave.z * sin(phase));
    vec2 slope = uWave.xy * ((uWave.z * k) * cos(phase));
    vNormal = normalize(vec3(-slope.x, 1.0, -slope.y));
    vTexCoord = aTexCoord + ((uWave.xy * uTime) * 0.0199999995529651641845703125);
    vec4 _103 = uViewProj * world;
    gl_Position = _103;
    vec4 _108 = gl_Position;
    _108.x = ((eyeSign != 0.0) && ((abs(_108.w - 1.0) > 9.9999997473787516355514526367188e-06) && (!isinf(_108.w)))) ? (_108.x + ((eyeSign * separation) * (_108.w - convergence))) : _108.x;
    vClipPos = _108;
    vec4 _111 = gl_Position;
    vec2 _116 = vec2(gl_Position.w);
    vec2 _120 = vec2(0.5);
    _111.x = ((eyeSign != 0.0) && ((abs(_111.w - 1.0) > 9.9999997473787516355514526367188e-06) && (!isinf(_111.w)))) ? (_111.x + ((eyeSign * separation) * (_111.w - convergence))) : _111.x;
    vScreenUV = ((_111.xy / _116) * 0.5) + _120;
    if ((eyeSign != 0.0) && ((abs(gl_Position.w - 1.0) > 9.9999997473787516355514526367188e-06) && (!isinf(gl_Position.w))))
    {
        float _193 = gl_Position.w - convergence;
        float _194 = eyeSign * separation;
        float _195 = _194 * _193;
        float _196 = gl_Position.x + _195;
        gl_Position.x = _196;
    }
}

