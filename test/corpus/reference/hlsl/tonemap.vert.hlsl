// stereoshift-expect: 2d
// D3D11 full-screen post vertex shader: triangle generated from SV_VertexID with a constant w of 1.0.

struct VSOutput
{
    float4 Position : SV_Position;
    float2 UV       : TEXCOORD0;
};

VSOutput VSMain(uint vertexId : SV_VertexID)
{
    VSOutput output;
    float2 uv = float2((vertexId << 1) & 2, vertexId & 2);
    output.UV = uv;
    // D3D texture space has v pointing down.
    output.Position = float4(uv.x * 2.0 - 1.0, 1.0 - uv.y * 2.0, 0.0, 1.0);
    return output;
}
