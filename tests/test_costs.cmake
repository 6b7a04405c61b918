# Included by ctest (TEST_INCLUDE_FILES, tests/CMakeLists.txt) after the discovered GoogleTest tests: the COST of
# the tests that take 5 s or more, in seconds as `ctest -j2` measured them (build/Testing/Temporary/
# CTestCostData.txt). ctest -j starts the most costly tests first, so that the short ones fill the cores at the
# end; it orders by these only where it has no timings of its own yet (a clean clone, CI): after a run, its
# measured times replace them. Only the order depends on them: a stale or missing entry costs wall time, never a
# result (a test that does not exist in this build, a module left out, is ignored).
set(mpm_test_costs
  Perforation.SphereThroughPlateRunsToItsEndWithClosedBooks 30
  Perforation.FailedAndErodedParticlesLeaveTheTimeStep 8
  ColumnCollapse.RunOutAndHeightOfAShortColumnAgainstLube2005 6
  SandPile.MohrCoulombFlankStopsAtTheFlowingSlopeLimit 10
  SandPile20Cells.FlankStopsAtTheFlowingSlopeLimitForBothModels 115
  StrengthReduction.GriffithsLaneSlopeFailsBetweenFactors135And1425 25
  EnergySentinelDisks.CpGimpDoesNotWarn 46
  Verify.AxisymmetricTaylorAnvilBandHoldsTheErrorAgainstTheFinestRun 38
  MmsCpdi.TwoD 35
  SceneFuzz.EveryMutatedSceneIsValidOrRefused 34
  EnergySentinelDisks.QuadraticBsplinesDoNotWarn 29
  MmsCpdi.ThreeD 17
  Vortex.TlmpmCubicBSpline 16
  Vortex.TlmpmBernstein 14
  Mms3D.TlmpmCubicBSpline 13
  EnergySentinelDisks.PicFractionDoesNotWarn 13
  EnergySentinelDisks.FlipWithHatsWarnsWithTheFlipHint 13
  Cli.EveryBadSceneIsRefusedAndNothingIsWritten 13
  RunOverrides.EveryExampleRunsThreeSteps 17
  EnergySentinelDisks.StopEndsTheProgramWithStatusThree 11
  ImplicitScheme.CollidingCylindersDissipateEnergyAndKeepMomenta 10
  CflBoundLongRun.MuslRunsAndDamps 10
  PlasticityScene.MillionParticleJohnsonCookBitIdenticalAcrossThreadCounts 9
  Mms3D.TlmpmBernstein 9
  ImplicitLargeStep.TaylorBarAt227MetresPerSecondHasTheFiniteElementShape 9
  LoveSulskyTaylorBar.ExplicitSchemesWithinTwoPercentOfFiniteElements 8
  HeatConduction.Plate2dWithTheTwoCellElementsAndCpdi 8
  ConformingDomains.TetrahedraOfACubeSumToItsVolume 8
  CflBoundLongRun.UsfGainsEnergyAndTheSentinelWarns 8
  TwoDisksContact.OtherSchemesAndShapes 7
  TensileNecking.CoarseNeckAtMidLengthAndFailure 7
  Mms2D.TlmpmSecondOrder 7
  Mms1D.MpmLargeDeformation 7
  HertzSphereAxisymmetric.PeakForceAndDurationApproachHertz 7
  Catalogue.EveryCaseRunsAtItsCoarsestResolution 7
  TwoDisksContact.Cpdi 6
  Mms3D.TlmpmLinear 6
  Mms1D.MpmSmallDeformation 6
  ImplicitLargeStep.AxisymmetricBarRunsAtSevenTimesTheExplicitBoundAndOnlyDissipates 6
  CflBoundLongRun.TlmpmGainsEnergyAndTheSentinelWarns 6
  AxisymmetricBarImpact.StrikerStopsAndTargetTakesItsVelocity 6
  Locking.ExplicitSchemesCarryAPressureCheckerboard 5
  ImplicitScheme.SpinningDiskKeepsEnergyAndMomentaAtTenTimesTheExplicitBound 5
)
while(mpm_test_costs)
  list(POP_FRONT mpm_test_costs name cost)
  set_tests_properties(${name} PROPERTIES COST ${cost})
endwhile()
