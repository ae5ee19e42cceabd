static const float Tint = 0.5;
