// Every texture unit, image unit and shader-storage binding point the testbed's programs
// bind, written once: C++ reads this table through testbed/glsl/units.h (as constants and
// as the list tests/units_test.cpp checks), GLSL through `#include "testbed/glsl/units.glsl"`,
// which declares each as `const int` for `layout(binding = ...)`. So a unit number is never
// written twice, and no shader or C++ call names one by its number.
//
// TESTBED_UNIT(kind, name, number, scope): kind Texture, Image or Buffer; scope the programs
// that bind the unit together: Shared units are bound beside any program's own (the
// receiver inputs, the shadow map, the revectorization library's depth image), the others
// within one technique's programs only, so two scopes may reuse a number but one scope and
// Shared may not. Image units stay below 8, the least GL_MAX_IMAGE_UNITS a GL 4.5 driver
// offers.
#ifndef TESTBED_UNIT
#define TESTBED_UNIT(kind, name, number, scope) const int name = number;
#endif

// Bound by every screen pass (receiver_inputs.h, shadow_map_pass.h).
TESTBED_UNIT(Texture, kGPositionTextureUnit, 0, Shared)    // receiver.glsl's uGPosition
TESTBED_UNIT(Texture, kGNormalTextureUnit, 1, Shared)      // receiver.glsl's uGNormal
TESTBED_UNIT(Texture, kShadowMapTextureUnit, 2, Shared)    // shadow_test.glsl's and depth_image.frag's uShadowMap, cascades.glsl's uShadowMaps
TESTBED_UNIT(Image, kDepthImageUnit, 5, Shared)            // revectorization.glsl's uShadowImage (depth_image.h)

// The techniques' own.
TESTBED_UNIT(Texture, kRpcfTileBoundsTextureUnit, 3, Rpcf)            // rpcf.glsl's uRpcfTiles
TESTBED_UNIT(Texture, kDiscontinuityMapTextureUnit, 3, Smsr2Pass)     // smsr_2pass_search.glsl's uDiscontinuityMap
TESTBED_UNIT(Texture, kSilhouetteMapTextureUnit, 3, SilhouetteMap)   // silhouette_map_visibility.frag's uSilhouetteMap
TESTBED_UNIT(Buffer, kSilhouetteEdgesBufferBinding, 0, SilhouetteMap)  // silhouette_map_edges.vert's Edges
TESTBED_UNIT(Texture, kMomentMapTextureUnit, 3, Prefiltered)          // visibility.frag's uMoments
TESTBED_UNIT(Texture, kBlurSourceTextureUnit, 4, Prefiltered)         // blur.frag's uSource

// EDTSM (edtsm.h) and its feature transforms.
TESTBED_UNIT(Texture, kEdtsmInputTextureUnit, 4, Edtsm)    // a pass's screen input: uHard, uIntensity
TESTBED_UNIT(Texture, kNearestSeedTextureUnit, 5, Edtsm)   // edtsm_penumbra.frag's uNearestSeed
TESTBED_UNIT(Texture, kTileKindsTextureUnit, 6, Edtsm)     // edtsm_filter_tiles.comp's uTileKinds
TESTBED_UNIT(Texture, kEdtSeedsTextureUnit, 7, Edtsm)      // the feature transforms' uSeeds
TESTBED_UNIT(Image, kEdtsmOutputImageUnit, 0, Edtsm)       // what a compute pass writes: uIntensity, uFiltered, uNearest
TESTBED_UNIT(Image, kTileKindsImageUnit, 1, Edtsm)         // edtsm_seeds.comp's and edtsm_penumbra.comp's uTileKinds
TESTBED_UNIT(Image, kTileSeedsImageUnit, 2, Edtsm)         // edtsm_penumbra_band.h's uTileSeeds
TESTBED_UNIT(Image, kTileMinDepthImageUnit, 3, Edtsm)      // edtsm_penumbra_band.h's uTileMinDepth
TESTBED_UNIT(Image, kEdtsmInputImageUnit, 4, Edtsm)        // uHardImage, uIntensityImage
TESTBED_UNIT(Image, kRowNearestImageUnit, 6, Edtsm)        // feature_transform.h's row pass result
TESTBED_UNIT(Image, kEnvelopeImageUnit, 7, Edtsm)          // feature_transform.h's parabola stacks
TESTBED_UNIT(Buffer, kTileListBufferBinding, 0, Edtsm)     // edtsm_filter_tiles.h's Tiles
TESTBED_UNIT(Buffer, kPenumbraRunsBufferBinding, 2, Edtsm)  // edtsm_penumbra_band.h's Runs
// The banded transform (feature_transform_banded.h) writes its result at
// kEdtsmOutputImageUnit.
TESTBED_UNIT(Image, kBandSeedsImageUnit, 1, BandedEdt)     // RG32I (bands, rows): a row band's (first, last) seed column
TESTBED_UNIT(Image, kBandCarryImageUnit, 2, BandedEdt)     // RG32I (bands, rows): the seed columns either side of the band
TESTBED_UNIT(Image, kBandRowNearestImageUnit, 3, BandedEdt)  // R32I, a texel a pixel: the row's nearest seed column
TESTBED_UNIT(Image, kLinksImageUnit, 4, BandedEdt)         // RG32I, a texel a pixel: a site's (previous, next) site
TESTBED_UNIT(Image, kBandEndsImageUnit, 6, BandedEdt)      // RG32I (columns, bands): a band's first and last site
TESTBED_UNIT(Image, kBandStartImageUnit, 7, BandedEdt)     // R32I (columns, bands): the site winning a band's first row

// The ground truth's shadow volumes (groundtruth/shadow_volumes.cpp).
TESTBED_UNIT(Texture, kVolumeCountTextureUnit, 3, GroundTruth)  // volume_visibility.frag's uCount

// The harness's shading pass (testbed/harness/shading.h), beside kGPositionTextureUnit.
TESTBED_UNIT(Texture, kShadingNormalTextureUnit, 3, Shading)      // shading.frag's uShadingNormal
TESTBED_UNIT(Texture, kShadingVisibilityTextureUnit, 4, Shading)  // shading.frag's uVisibility

// Out-of-tree techniques (plugins, technique/plugin.h): a plugin cannot add lines to this
// table, so these are its own, beside the Shared ones and apart from every in-tree
// technique's (texture units 8 to 15, past all of theirs). Bind and name them like any
// other: glBindTextureUnit(testbed::kPluginTextureUnit0, …) and
// layout(binding = kPluginTextureUnit0) or program.set("uMine", testbed::kPluginTextureUnit0).
TESTBED_UNIT(Texture, kPluginTextureUnit0, 8, Plugin)
TESTBED_UNIT(Texture, kPluginTextureUnit1, 9, Plugin)
TESTBED_UNIT(Texture, kPluginTextureUnit2, 10, Plugin)
TESTBED_UNIT(Texture, kPluginTextureUnit3, 11, Plugin)
TESTBED_UNIT(Texture, kPluginTextureUnit4, 12, Plugin)
TESTBED_UNIT(Texture, kPluginTextureUnit5, 13, Plugin)
TESTBED_UNIT(Texture, kPluginTextureUnit6, 14, Plugin)
TESTBED_UNIT(Texture, kPluginTextureUnit7, 15, Plugin)
TESTBED_UNIT(Image, kPluginImageUnit0, 0, Plugin)
TESTBED_UNIT(Image, kPluginImageUnit1, 1, Plugin)
TESTBED_UNIT(Image, kPluginImageUnit2, 2, Plugin)
TESTBED_UNIT(Image, kPluginImageUnit3, 3, Plugin)
TESTBED_UNIT(Buffer, kPluginBufferBinding0, 0, Plugin)
TESTBED_UNIT(Buffer, kPluginBufferBinding1, 1, Plugin)
TESTBED_UNIT(Buffer, kPluginBufferBinding2, 2, Plugin)
TESTBED_UNIT(Buffer, kPluginBufferBinding3, 3, Plugin)

// The GLSL unit tests' probes.
TESTBED_UNIT(Texture, kProbeATextureUnit, 3, Probe)
TESTBED_UNIT(Texture, kProbeBTextureUnit, 4, Probe)
TESTBED_UNIT(Buffer, kProbeInputBufferBinding, 0, Probe)
TESTBED_UNIT(Buffer, kProbeOutputBufferBinding, 1, Probe)
