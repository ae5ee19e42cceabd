float3 ApplyAmbient(float3 color) { return color * 0.2f + 0.1f; }
