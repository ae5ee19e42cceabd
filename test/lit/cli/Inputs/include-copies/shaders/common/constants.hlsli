static const float kBillboardSize = 0.25;
