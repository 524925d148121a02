// The image units of the feature transform's scratch images (feature_transform.h), kept
// clear of the units its including shaders use themselves (0 to 4).
const int kRowNearestUnit = 6;  // R32I: pass 1's nearest seed column per pixel, -1 if none
const int kEnvelopeUnit = 7;    // RG32I: pass 2's parabola stacks, one column per column
