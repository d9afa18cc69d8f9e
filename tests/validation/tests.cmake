# Validation tests: real runs compared with published values (label "validation"); the long ones also
# carry the label "slow" and are left out of CI (run them with `ctest -L slow`).
add_executable(chute_validation_tests
  ${CMAKE_CURRENT_LIST_DIR}/test_lid_driven_cavity.cpp
  ${CMAKE_CURRENT_LIST_DIR}/test_poiseuille.cpp
  ${CMAKE_CURRENT_LIST_DIR}/test_fixed_bodies.cpp
  ${CMAKE_CURRENT_LIST_DIR}/test_moving_bodies.cpp
  ${CMAKE_CURRENT_LIST_DIR}/test_bluff_bodies.cpp
  ${CMAKE_CURRENT_LIST_DIR}/test_free_bodies.cpp
  ${CMAKE_CURRENT_LIST_DIR}/test_turbulence.cpp
  ${CMAKE_CURRENT_LIST_DIR}/test_case_fuzz_runs.cpp
  $<TARGET_OBJECTS:chute_gtest_main>)
target_link_libraries(chute_validation_tests PRIVATE chute_run GTest::gtest)
target_compile_definitions(chute_validation_tests PRIVATE CHUTE_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
                                                          CHUTE_BINARY="$<TARGET_FILE:chute>")

# Runs a validation test on `ranks` MPI ranks.
function(chute_validation name filter ranks labels)
  add_test(NAME ${name}
           COMMAND ${MPIEXEC_EXECUTABLE} ${MPIEXEC_NUMPROC_FLAG} ${ranks} --allow-run-as-root --oversubscribe
                   $<TARGET_FILE:chute_validation_tests> --gtest_filter=${filter})
  set_tests_properties(${name} PROPERTIES LABELS "${labels}" PROCESSORS ${ranks})
endfunction()

chute_validation(cavity_re100_64 Cavity.Re100Grid64 2 "validation")
chute_validation(cavity_re1000_128 Cavity.Re1000Grid128 2 "validation")
chute_validation(cavity_re100_128 Cavity.Re100Grid128 2 "validation")
chute_validation(poiseuille_stretched Poiseuille.StretchedGridSecondOrder 1 "validation")
chute_validation(poiseuille_inflow_outflow Poiseuille.InflowOutflowChannelKeepsTheParabola 2 "validation")
chute_validation(poiseuille_zero_stress Poiseuille.ZeroStressOutflowGivesTheExactPressureGradient 2 "validation")
chute_validation(cavity_re1000_128_van_leer Cavity.Re1000Grid128VanLeer 2 "validation")
chute_validation(cavity_re1000_128_koren Cavity.Re1000Grid128Koren 2 "validation")
chute_validation(cavity_re1000_256 Cavity.Re1000Grid256 2 "validation;slow")

# Immersed bodies
chute_validation(dfg_2d1 FixedBodies.SchaeferTurek2D1 2 "validation")
chute_validation(dfg_2d1_sharp FixedBodies.SchaeferTurek2D1Sharp 2 "validation")
# Known failure, kept as the record of the sharp-corners issue (docs/validation.md, "Sharp interface"): the sharp
# interface's surface-stress drag converges at order 1.45 over D/h 20 / 40 / 80, short of the 1.5 the issue asks.
chute_validation(dfg_2d1_sharp_convergence FixedBodies.SchaeferTurek2D1SharpConvergence 2 "validation;slow;known_failure")
# Known failure, kept as the record (docs/validation.md, DFG 2D-1): the surface-stress drag (b) converged at
# order 0.83 from D/h 40 to 80 with the old probes, short of the first order the test asks. The present rule
# (probes 2.5-4.5 cells, the wall's pressure gradient) fixed the pressure part. With the smoothed kernel and
# converged forcing (2026-11-24) (a) is in the band at D/h 20, 40 and 80 and (b) reads 5.4491 / 5.4948 / 5.5290
# (errors 0.130 / 0.085 / 0.0505: closer than before, but order 0.75 from 40 to 80; the viscous part still rises).
# `ctest -L slow -LE known_failure` runs the rest of the slow suite.
chute_validation(dfg_2d1_convergence FixedBodies.SchaeferTurek2D1Convergence 2 "validation;slow;known_failure")
# Known failure, kept as the record of the forces issue's item 5 (docs/validation.md, DFG 2D-2): the unsteady lift
# is 6 % low at D/h 40.
chute_validation(dfg_2d2 FixedBodies.SchaeferTurek2D2 2 "validation;slow;known_failure")
# Known failure, kept as the record of the sharp-corners issue: ghost faces read C_L max 0.981 at D/h 40 (band 0.99-1.01)
# and C_D max 2.3 % over its band at D/h 20.
chute_validation(dfg_2d2_sharp FixedBodies.SchaeferTurek2D2Sharp 2 "validation;slow;known_failure")
# Known failure, kept as the record of the sharp-corners issue (docs/validation.md, "Sharp interface", tenth step): a
# sharp square held in a stream reads its drag within 1 % of body-fitted when its sides lie on grid lines, but -8.6 %
# to +4.3 % (and a lateral force) when they lie within cells.
chute_validation(sharp_square_offsets FixedBodies.SharpSquareDragIndependentOfItsPlaceInTheCell 2 "validation;slow;known_failure")
chute_validation(sharp_square_symmetric FixedBodies.SharpSquareOnALineFeelsNoForceAcrossASymmetricStream 2 "validation")
# Known failure, kept as the record of the sharp-corners issue (docs/validation.md, "Sharp interface", eleventh step):
# the force of a sharp body jumps as its surface crosses the place where the faces' classification switches (ghost
# faces: -10 % / +15 % either side of a tangential face's centre; forcing faces: -5 % / +11 % either side of a line).
chute_validation(sharp_force_continuity FixedBodies.SharpForceContinuousAsTheSurfaceCrossesFaces 2 "validation;slow;known_failure")
# Cut momentum (numerics.ibm.cut_momentum): the same bed continuous, and a face-on square's drag independent of its place.
chute_validation(sharp_cut_momentum_couette FixedBodies.SharpCutMomentumHoldsCouetteFlowExactly 2 "validation")
chute_validation(sharp_cut_momentum_continuity FixedBodies.SharpCutMomentumForceContinuousAsTheSurfaceCrossesFaces 2 "validation")
chute_validation(sharp_cut_momentum_poiseuille FixedBodies.SharpCutMomentumHoldsPoiseuilleFlowBetweenTwoBodies 2 "validation")
chute_validation(sharp_cut_momentum_face_on FixedBodies.SharpCutMomentumFaceOnSquareIndependentOfItsPlace 2 "validation")
chute_validation(added_mass_square_face MovingBodies.AddedMassOfSquareAlongFaceNormal 2 "validation")
chute_validation(added_mass_square_diagonal MovingBodies.AddedMassOfSquareAlongDiagonal 2 "validation")
chute_validation(added_mass_square_body_fitted MovingBodies.AddedMassOfSquareBodyFitted 2 "validation")
chute_validation(inclined_plane_no_through_flow MovingBodies.NoFlowThroughAnInclinedPlane 2 "validation")
# The square's pair passes since the smoothed kernel with 10 iterations (moving / fixed 1.0094, ripple 0.97 %).
# The study block's is a known failure, kept as the record: ripple 0.91 %, but (a) moving / fixed 1.0514. The fixed
# block's drag follows the slip the projection leaves (docs/validation.md, "The fixed block's drag follows its
# slip"): with numerics.ibm.projection_passes 8 the means agree (1.0065) but the ripple is 1.79 %.
chute_validation(galilean_pair_square_re100 MovingBodies.GalileanPairSquareRe100 2 "validation;slow")
chute_validation(galilean_pair_study_block MovingBodies.GalileanPairStudyBlockAtTerminalSpeed 2 "validation;slow;known_failure")
chute_validation(galilean_pair_study_block_sharp MovingBodies.GalileanPairStudyBlockSharpInAWindow 2 "validation;slow")
chute_validation(galilean_pair_sharp_circle MovingBodies.GalileanPairSharpCutMomentumCircle 2 "validation")
chute_validation(galilean_pair_sharp_square MovingBodies.GalileanPairSharpCutMomentumSquare 2 "validation")
chute_validation(cylinder_re40 BluffBodies.CylinderRe40 2 "validation;slow")
chute_validation(cylinder_re100 BluffBodies.CylinderRe100 2 "validation;slow")
chute_validation(square_cylinder_re100 BluffBodies.SquareCylinderRe100 2 "validation;slow")
chute_validation(square_cylinder_re100_body_fitted BluffBodies.SquareCylinderRe100BodyFittedConverges 2 "validation;slow")
chute_validation(oscillating_cylinder_dutsch BluffBodies.OscillatingCylinderDutsch 2 "validation;slow")

# Free bodies
chute_validation(free_neutral_disc_at_rest FreeBodies.NeutrallyBuoyantDiscStaysAtRest 2 "validation")
chute_validation(free_light_disc_rises FreeBodies.LightDiscRisesWithItsAddedMass 2 "validation")
chute_validation(settling_disc_glowinski FreeBodies.SettlingDiscReachesTheGlowinskiTerminalReynoldsNumber 2 "validation")
chute_validation(free_block_start FreeBodies.StudyBlockStartsWithItsPotentialFlowAcceleration 2 "validation")
# Issue 15's impacts: the bed and the 45 degree slope with the step halved (about 2 minutes on 2 ranks), and
# the wet restitution of a contact resolved by the flow (about 1 minute).
chute_validation(impacts_step_independent FreeBodies.ImpactsDoNotDependOnTheTimeStep 2 "validation;slow")
chute_validation(wet_rebound_resolved_contact FreeBodies.ResolvedContactInWaterReboundsNearTheDryRestitution 2 "validation;slow")
chute_validation(free_body_start_inside_obstacle FreeBodies.StartInsideAnObstacleIsAnError 1 "validation")

# Turbulence
chute_validation(turbulent_channel Turbulence.ChannelBulkVelocity 2 "validation")
chute_validation(turbulent_channel_first_cell Turbulence.ChannelIndependentOfTheFirstCell 2 "validation")
chute_validation(turbulent_channel_friction Turbulence.ChannelFrictionCoefficient 2 "validation;slow")
chute_validation(free_fall_block_k_epsilon Turbulence.StudyBlockFallsAtTheExperimentsSpeed 2 "validation;slow")
chute_validation(free_fall_block_window Turbulence.StudyBlockFallsAlikeInAWindowThatFollowsIt 2 "validation;slow")
chute_validation(free_fall_block_body_fitted Turbulence.StudyBlockFallsBodyFittedConverged 2 "validation;slow")
chute_validation(free_fall_block_body_fitted_layers Turbulence.StudyBlockFallsAlikeWithLayersAndATranslatingGrid 2 "validation;slow")
chute_validation(free_fall_block_sharp Turbulence.StudyBlockFallsOnTheSharpCarrierAsBodyFitted 2 "validation;slow")
chute_validation(free_fall_block_sharp_shedding Turbulence.StudyBlockShedsOnTheSharpCarrierAsBodyFitted 2 "validation;slow")
chute_validation(slope_runout_water_air Turbulence.SlopeRunoutInWaterIsShorterThanInAir 2 "validation;slow")
chute_validation(slope_runout_both_modes Turbulence.StudySlopeRunoutAgreesInBothModes 2 "validation;slow")
chute_validation(bed_cushion_body_fitted Turbulence.StudyBlockOnTheBedIsCushionedByTheSqueezedWater 2 "validation;slow")
chute_validation(square_cylinder_re22000 Turbulence.SquareCylinderRe22000 2 "validation;slow")
chute_validation(square_cylinder_re22000_body_fitted Turbulence.SquareCylinderRe22000BodyFitted 2 "validation;slow")
chute_validation(square_cylinder_re22000_sharp Turbulence.SquareCylinderRe22000SharpMatchesBodyFitted 2 "validation;slow")
chute_validation(sharp_cut_momentum_held_block Turbulence.SharpCutMomentumHeldBlockIndependentOfItsPlace 2 "validation;slow")
chute_validation(square_cylinder_re22000_cut_momentum Turbulence.SquareCylinderRe22000CutMomentumMatchesBodyFitted 2 "validation;slow")
chute_validation(square_cylinder_re22000_empty Turbulence.SquareCylinderDomainWithoutBodyMakesNoTurbulence 2 "validation")

# Fuzzing whole runs (test_case_fuzz_runs.cpp): the chute tool on the mutated example cases, two steps each,
# about 8 min on 2 cores. Started without mpiexec: a tool started from an mpirun-launched rank inherits the job's
# environment and fails in MPI_Init (tests/CMakeLists.txt, unit_np2). A case that reaches the 30 s limit is run again
# under a limit scaled by its cells (40 us per cell: the free fall with domain.y.cells x100, 11.5 M cells, runs its two
# steps in 185 s against 460 s; docs/validation.md, "Case fuzz of whole runs").
add_test(NAME case_fuzz_runs COMMAND $<TARGET_FILE:chute_validation_tests> --gtest_filter=CaseFuzzRuns.*)
set_tests_properties(case_fuzz_runs PROPERTIES LABELS "slow;fuzz" TIMEOUT 5400)
