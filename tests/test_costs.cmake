# CTest starts the costliest tests first when it runs them in parallel (`ctest -j`), from
# Testing/Temporary/CTestCostData.txt once a run has written it; a fresh clone has none, so
# without these its longest tests start last and leave one core idle at the end.
# The figures are seconds measured on the shared two-core machine under load
# (docs/performance.md "Suite time"): only their order matters. Included after the
# discovered GoogleTest tests (TEST_INCLUDE_FILES, tests/CMakeLists.txt); a name that is not
# built (no viewer, no Embree) is ignored.
set(testbed_test_costs
  RevectorizationGlsl.EveryDepthLayoutGivesTheSameNumbers 300
  RevectorizationGlsl.RevectorizedEdgeIsCloserToTheLineThanTheStair 79
  RevectorizationScene.AgainstShadowVolumesOnTheBundledScenes 77
  RevectorizationGlsl.ConservativeLineIsTheTrueLineHalfATexelIntoTheLitSide 63
  RevectorizationGlsl.RpcfWithKernelOneEqualsItsBase 55
  RevectorizationGlsl.RpcfRegularBlockFromTheDiagonalEqualsAllTaps 50
  RevectorizationGlsl.RpcfScreenPassEqualsThePlainLoop 45
  PrefilteredScenes.VisibilityIsFiniteOnEveryBundledScene 40
  RevectorizationGlsl.WidestRpcfKernelsAreTheMeanOfTheirTaps 39
  RevectorizationGlsl.GatheredClassificationEqualsFetched 37
  FeatureTransform.BandedReturnsTheTwoPassSeedAndTheLeastTiedOne 35
  Edtsm.ImprovedOverestimatesLessAgainstShadowVolumes 32
  RevectorizationGlsl.RsmssValuesAreInTheUnitInterval 32
  SeparableBlur.PackedIntermediateGivesThePlainResultBitForBit 31
  Edtsm.PaperPathWithTheBandedEdtMatchesTheFastPathBitForBit 29
  Edtsm.FastPathMatchesTheReferencePipelineBitForBit 29
  RevectorizationGlsl.ImprovedVisibilityIsSymmetricInLitAndShadow 28
  SmsrTwoPass.PassesMemoryAndErrorAgainstSinglePass 25
  SilhouetteMapScene.BundledScenesAgainstSm 23
  StencilVolumes.EveryBundledSceneMatchesTheFastPathAtTwoSizes 18
  SampledTexels.HoldEveryReceiversBilinearFootprint 17
  RevectorizationScene.DebugViewsAreReturnedOnlyWhenAsked 16
  PcfGroundTruth.Bunny 14
  PcfImage.ValuesAreInTheUnitIntervalAndTheBoxFilterCountsLitTaps 14
  PrefilteredScenes.VisibilityIsFiniteWithDepthsAtBothEndsOfTheRange 14
  PrefilteredScenes.VisibilityIsFiniteWithAHugeDepthRange 14
  RevectorizationScene.RpcfKernelOneEqualsItsBaseOnAScene 13
  DepthPassCounting.BundledScenesMatchDepthFail 13
  FeatureTransform.RandomMasksMatchBruteForceAtEverySizeAndDensity 13
  PcfGroundTruth.DragonSun 12
  # End to end: a cluster, many `testbed` runs each.
  Slurm.CorpusSweepKilledShardResumesAndMergesAsAnUninterruptedRun 200
  CliSweep.AKilledSweepResumesWhereItStopped 60)
while(testbed_test_costs)
  list(POP_FRONT testbed_test_costs name cost)
  set_tests_properties("${name}" PROPERTIES COST ${cost})
endwhile()
