// stereoshift-expect: already-stereo
// D3D12 view instancing (SM 6.1): the view-projection matrix of each eye is picked by SV_ViewID.
// Already stereo: copied unchanged.
cbuffer FrameConstants : register(b0) {
  float4x4 ViewProjection[2];
};
cbuffer ObjectConstants : register(b1) {
  float4x4 World;
};

struct VSInput {
  float3 position : POSITION;
  float2 uv : TEXCOORD0;
};

struct PSInput {
  float4 position : SV_POSITION;
  float2 uv : TEXCOORD0;
};

PSInput main(VSInput input, uint viewID : SV_ViewID) {
  PSInput output;
  float4 world = mul(World, float4(input.position, 1.0f));
  output.position = mul(ViewProjection[viewID], world);
  output.uv = input.uv;
  return output;
}
