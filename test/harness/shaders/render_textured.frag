#version 450
// HUD quad: maps the pixel rectangle pc.rect (x, y, w, h) onto the texture.
layout(set = 0, binding = 0) uniform sampler2D tex;
layout(push_constant) uniform Push { vec4 rect; } pc;
layout(location = 0) out vec4 outColour;
void main() { outColour = texture(tex, (gl_FragCoord.xy - pc.rect.xy) / pc.rect.zw); }
