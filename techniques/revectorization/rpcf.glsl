// The kernel width shared by the two RPCF variants (rpcf_smsr.glsl, rpcf_rsmss.glsl).
uniform int uKernel;  // odd: the k×k block is centred on the receiver's texel
