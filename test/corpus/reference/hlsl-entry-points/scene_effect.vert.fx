// stereoshift-expect: shift
// Effects 10 file in SDK style: RenderSceneVS/RenderScenePS named only by the technique10 passes.
cbuffer cbPerObject
{
    float4x4 g_mWorldViewProjection;
    float4 g_MaterialDiffuseColor;
};

struct VS_OUTPUT
{
    float4 Position : SV_POSITION;
    float4 Diffuse : COLOR0;
};

// ---- stereoshift: stereo parameters and clip-space shift (injected) ----
cbuffer StereoParams : register(b1)
{
    float eyeSign;
    float separation;
    float convergence;
};

VS_OUTPUT stereoshift_shift_VS_OUTPUT(VS_OUTPUT stereoshift_v)
{
    if (eyeSign != 0.0f && abs(stereoshift_v.Position.w - 1.0f) > 9.99999975e-06f && !isinf(stereoshift_v.Position.w))
    {
        precise float stereoshift_x = stereoshift_v.Position.x + (eyeSign * separation) * (stereoshift_v.Position.w - convergence);
        stereoshift_v.Position.x = stereoshift_x;
    }
    return stereoshift_v;
}
// ---- end stereoshift ----

VS_OUTPUT RenderSceneVS( float4 vPos : POSITION, float3 vNormal : NORMAL )
{
    VS_OUTPUT Output;
    Output.Position = mul( vPos, g_mWorldViewProjection );
    Output.Diffuse = g_MaterialDiffuseColor * saturate( dot( vNormal, float3( 0, 1, 0 ) ) * 0.5 + 0.5 );
    return stereoshift_shift_VS_OUTPUT(Output);
}

float4 RenderScenePS( VS_OUTPUT In ) : SV_TARGET
{
    return In.Diffuse;
}

technique10 RenderScene
{
    pass P0
    {
        SetVertexShader( CompileShader( vs_4_0, RenderSceneVS() ) );
        SetGeometryShader( NULL );
        SetPixelShader( CompileShader( ps_4_0, RenderScenePS() ) );
    }
}
