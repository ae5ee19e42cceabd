#include "constants.hlsli"
cbuffer Camera : register(b0) { float4x4 ViewProj; };
