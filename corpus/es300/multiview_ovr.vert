#version 300 es
// stereoshift-expect: already-stereo
// OpenGL ES single-pass stereo (GL_OVR_multiview2), as mobile VR samples write it: the eye's
// view-projection matrix is indexed by gl_ViewID_OVR. Already stereo: copied unchanged.
#extension GL_OVR_multiview2 : require
layout(num_views = 2) in;

uniform mat4 uViewProjection[2];
uniform mat4 uModel;

in vec3 aPosition;
in vec2 aTexCoord;
out vec2 vTexCoord;

void main() {
  vTexCoord = aTexCoord;
  gl_Position = uViewProjection[gl_ViewID_OVR] * uModel * vec4(aPosition, 1.0);
}
