# `poresph image slice`: a section of the real Berea image (ROCKS) as a PNG, a colour per label,
# against tests/baselines/berea_section_z40.png (vtkTesting's difference, threshold 0.15: the PNG
# is one a standard reader takes), and a section 40 voxels away differs from it (the comparison
# bites; the next section passes the threshold: 0.15 forgives one-pixel shifts).
include(${CMAKE_CURRENT_LIST_DIR}/run_poresph.cmake)
file(MAKE_DIRECTORY ${WORK})
foreach(z 40 80)
  run_poresph(0 image slice ${ROCKS}/berea_110.raw --dimensions 110 110 110 --axis z --index ${z}
              --out ${WORK}/berea_z${z}.png)
endforeach()
run_poresph(0 image slice ${ROCKS}/berea_110.raw --dimensions 110 110 110 --axis x --index 40 --scale 3
            --out ${WORK}/berea_x40.png)
if(NOT out MATCHES "330 x 330 pixels \\(y to the right, z up\\)" OR NOT out MATCHES "label 0: #081840, [0-9]+ voxels \\(pore\\)")
  message(FATAL_ERROR "image slice: ${out}")
endif()
set(baseline ${SRC}/tests/baselines/berea_section_z40.png)
if(DEFINED ENV{UPDATE_BASELINES})
  file(COPY_FILE ${WORK}/berea_z40.png ${baseline})
endif()
execute_process(COMMAND ${IMAGE_DIFF} ${WORK}/berea_z40.png ${baseline} ${WORK} RESULT_VARIABLE rc OUTPUT_VARIABLE o)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the section differs from ${baseline}: ${o} (actual and diff in ${WORK}; UPDATE_BASELINES=1 accepts it)")
endif()
execute_process(COMMAND ${IMAGE_DIFF} ${WORK}/berea_z80.png ${baseline} ${WORK}/next RESULT_VARIABLE rc OUTPUT_VARIABLE o)
if(rc EQUAL 0)
  message(FATAL_ERROR "the section at z = 80 matches the baseline too: the comparison does not bite (${o})")
endif()
message(STATUS "image section test passed")
