# The solver built again in mixed precision (solver/core/config.hpp) beside a double build, and
# what CI runs in it: the validations named below (the others with `validate --full` or by hand in
# a mixed build: VALIDATION.md "Mixed precision") and the cross-precision restarts
# (tests/mixed_precision_cli.sh). Solver only: no CUDA, ParaView or dashboard, which precision
# does not touch.
include(ExternalProject)
set(PORESPH_MIXED_DIR ${CMAKE_BINARY_DIR}/mixed)
ExternalProject_Add(poresph_mixed
  SOURCE_DIR ${PROJECT_SOURCE_DIR}
  BINARY_DIR ${PORESPH_MIXED_DIR}
  CMAKE_ARGS -DCMAKE_BUILD_TYPE=Release -DPORESPH_PRECISION=mixed -DPORESPH_CUDA=OFF -DPORESPH_PARAVIEW=OFF
             -DPORESPH_DASHBOARD=OFF -DPORESPH_TESTS=OFF -DPORESPH_DEPS_DIR=${PORESPH_DEPS_DIR}
             -DPORESPH_ROCKS_DIR=${PORESPH_ROCKS_DIR}
  BUILD_COMMAND ${CMAKE_COMMAND} --build <BINARY_DIR> --target poresph
  INSTALL_COMMAND ""
  BUILD_ALWAYS ON  # its own build decides what changed
  BUILD_BYPRODUCTS ${PORESPH_MIXED_DIR}/solver/poresph)
set(PORESPH_MIXED ${PORESPH_MIXED_DIR}/solver/poresph)

set(PORESPH_MIXED_VALIDATIONS kernels poiseuille_2d poiseuille_couette two_phase_poiseuille_2d voxel_permeability
    laplace_bubble_2d vibrating_rod_1d oscillating_plate_2d softening_bar_2d elastic_cube_3d lame_cylinder_2d
    rigid_top_3d settling_cylinder_2d)
foreach(name IN LISTS PORESPH_MIXED_VALIDATIONS)
  add_test(NAME mixed_validate_${name} COMMAND ${PORESPH_MIXED} validate ${name})
  set_tests_properties(mixed_validate_${name} PROPERTIES LABELS "validation;mixed" ENVIRONMENT OMP_NUM_THREADS=1
                                                         SKIP_RETURN_CODE 77)
endforeach()
if(PORESPH_HAVE_HDF5)
  set(mpiexec "")
  if(PORESPH_HAVE_MPI)
    set(mpiexec ${MPIEXEC_EXECUTABLE})
  endif()
  add_test(NAME mixed_precision_cli COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/mixed_precision_cli.sh $<TARGET_FILE:poresph>
                                            ${PORESPH_MIXED} ${PROJECT_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/mixed_precision_cli ${mpiexec})
  set_tests_properties(mixed_precision_cli PROPERTIES LABELS "cli;mixed")
endif()
