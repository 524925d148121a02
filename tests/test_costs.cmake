# CTest starts the costliest tests first when it runs them in parallel (`ctest -j`), from
# Testing/Temporary/CTestCostData.txt once a run has written it; a fresh clone has none, so
# without these its longest tests start last and leave one core idle at the end.
# The figures are seconds from a whole run on the shared two-core machine (load about 8,
# docs/performance.md "Suite time"): only their order matters. Included after the
# discovered GoogleTest tests (TEST_INCLUDE_FILES, tests/CMakeLists.txt); a name that is not
# built (no viewer, no Embree) is ignored.
set(testbed_test_costs
  Slurm.CorpusSweepKilledShardResumesAndMergesAsAnUninterruptedRun 35
  Edtsm.PaperPathWithTheBandedEdtMatchesTheFastPath 34
  RevectorizationGlsl.RpcfWithKernelOneEqualsItsBase 32
  RevectorizationScene.AgainstShadowVolumesOnTheBundledScenes 32
  HostileSweep.SpecsAreReadStrictlyAndCappedBeforeAnythingRenders 31
  Paths.BothPathsGiveTheSameVisibility 30
  CliSweep.AKilledSweepResumesWhereItStopped 24
  PrefilteredScenes.VisibilityIsFiniteOnEveryBundledScene 22
  Edtsm.FastPathMatchesTheReferencePipeline 20
  RevectorizationGlsl.EveryDepthLayoutGivesTheSameNumbers 18
  RevectorizationGlsl.GatheredClassificationEqualsFetched 14
  RevectorizationGlsl.WidestRpcfKernelsAreTheMeanOfTheirTaps 14
  CliSweep.BadSpecsAndShardsAreOneLineAndWriteNothing 13
  SeparableBlur.PackedIntermediateGivesThePlainResultBitForBit 12
  CliSweep.WholeRunWritesRecordsTableAndFigure 11
  RevectorizationGlsl.RsmssValuesAreInTheUnitInterval 11
  HostileScene.SceneFilesThatAreNotRegularFilesAreRefusedAtOnce 10
  SmsrTwoPass.PassesMemoryAndErrorAgainstSinglePass 10
  ViewerTest.ScriptVisitingEveryTechniqueGivesCompareImages 10
  RevectorizationGlsl.ImprovedVisibilityIsSymmetricInLitAndShadow 9
  CliBadInput.OptionsAndScenesAreRejectedWithOneLine 9
  Edtsm.ImprovedOverestimatesLessAgainstShadowVolumes 9)
while(testbed_test_costs)
  list(POP_FRONT testbed_test_costs name cost)
  set_tests_properties("${name}" PROPERTIES COST ${cost})
endwhile()
