#version 450
// stereoshift-expect: fragment
// Cascaded shadow-map fragment shader: alpha-tested depth-only output for cutout materials.

layout(set = 1, binding = 0) uniform sampler2D alphaTex;

layout(set = 1, binding = 1) uniform CutoutUBO {
    float alphaCutoff;
    float mipBias;
} cutout;

layout(location = 0) in vec2 inUV;

void main()
{
    float alpha = texture(alphaTex, inUV, cutout.mipBias).a;
    if (alpha < cutout.alphaCutoff)
        discard;
    // Depth is written by fixed function; no colour attachment in this pass.
}
