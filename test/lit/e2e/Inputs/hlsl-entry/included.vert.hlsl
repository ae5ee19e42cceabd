#include "camera_vs.hlsli"
