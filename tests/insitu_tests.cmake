# End to end: the solver runs a short dam break with two Catalyst pipelines, headless (its own
# Xvfb, or none with an EGL/OSMesa ParaView), every frame rendered; images, settings, extracts and the in-situ timing must be there, the extracts must hold
# the solver's values, `figures` must re-render the sequence from the extracts, and --live with
# nobody listening must not stop the run.
cmake_minimum_required(VERSION 3.24)
include(${CMAKE_CURRENT_LIST_DIR}/run_poresph.cmake)

file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
file(READ ${SRC}/cases/dam_break_3d.toml text)
string(REPLACE "end = 20.0" "end = 0.02" text "${text}")
string(REPLACE "extract_interval = 1.0" "extract_interval = 0.005" text "${text}")
string(APPEND text "\n[visualisation]\npipelines = [\"phases\"]\ninterval = 0.005\nimage_size = [320, 240]\n")
file(WRITE ${WORK}/db_dropping.toml "${text}")
string(APPEND text "every_frame = true\n")
file(WRITE ${WORK}/db.toml "${text}")

run_poresph(0 run ${WORK}/db.toml --out ${WORK}/run --pipeline pressure --quiet)
file(READ ${WORK}/run/log.txt log)
if(OFFSCREEN_PARAVIEW)
  if(NOT (log MATCHES "ParaView renders off-screen"))
    message(FATAL_ERROR "an EGL/OSMesa ParaView should render off-screen: ${log}")
  endif()
elseif(NOT (log MATCHES "started Xvfb on :[0-9]+"))
  message(FATAL_ERROR "no own Xvfb without a display: ${log}")
endif()
foreach(p phases pressure)
  foreach(v 3d slab)
    foreach(k 000000 000004)
      if(NOT (EXISTS ${WORK}/run/images/${p}/${v}_${k}.png))
        message(FATAL_ERROR "missing images/${p}/${v}_${k}.png")
      endif()
    endforeach()
  endforeach()
endforeach()
if(NOT (EXISTS ${WORK}/run/images/visualisation.json))
  message(FATAL_ERROR "missing images/visualisation.json")
endif()
if(NOT (EXISTS ${WORK}/run/extracts/slab_000004.pvtp))
  message(FATAL_ERROR "missing the slab extract")
endif()
file(READ ${WORK}/run/summary.json summary)
string(JSON frames GET "${summary}" insitu frames)
if(NOT (frames EQUAL 5))
  message(FATAL_ERROR "expected 5 in-situ frames (0, 0.005, ..., 0.02 s), summary says ${frames}")
endif()
file(GLOB vtps ${WORK}/run/extracts/particles_*.vtp)
list(LENGTH vtps n)
if(NOT (n EQUAL 5))
  message(FATAL_ERROR "expected an extract per frame, found ${n}")
endif()
# Inline data only: ParaView 5.11 cannot read an appended section with Debian 12's current expat.
file(GLOB slab_pieces ${WORK}/run/extracts/slab_000004/*.vtp)
foreach(f ${vtps} ${slab_pieces})
  file(READ ${f} head LIMIT 8192)
  if(head MATCHES "<AppendedData")
    message(FATAL_ERROR "${f} has an appended data section; extracts must be written inline (DataMode Binary)")
  endif()
endforeach()
if(NOT slab_pieces)
  message(FATAL_ERROR "the slab extract has no pieces in extracts/slab_000004/")
endif()

# The default: the render thread drops the frames it has no time for (never the solver's time);
# what it renders is the same picture, and rendered + dropped frames are the output steps.
run_poresph(0 run ${WORK}/db_dropping.toml --out ${WORK}/dropping --quiet)
file(READ ${WORK}/dropping/summary.json summary)
string(JSON rendered GET "${summary}" insitu frames)
string(JSON dropped GET "${summary}" insitu dropped_frames)
math(EXPR outputs "${rendered} + ${dropped}")
if(NOT (outputs EQUAL 5 AND rendered GREATER_EQUAL 2))
  message(FATAL_ERROR "expected 5 output steps, frame 0 and the last among those rendered: ${rendered} rendered, ${dropped} dropped")
endif()
file(STRINGS ${WORK}/dropping/images/frames.csv rows)
list(LENGTH rows nrows)
list(GET rows -1 last)
math(EXPR expected_rows "${rendered} + 1")
if(NOT (nrows EQUAL expected_rows AND last MATCHES ",0\\.0(2|19999+[0-9]*)$"))
  message(FATAL_ERROR "images/frames.csv should list the ${rendered} rendered frames, the last at t = 0.02: ${rows}")
endif()
execute_process(COMMAND ${IMAGE_DIFF} ${WORK}/dropping/images/phases/3d_000000.png ${WORK}/run/images/phases/3d_000000.png
                        ${WORK}/dropping RESULT_VARIABLE rc OUTPUT_VARIABLE out)
if(NOT (rc EQUAL 0))
  message(FATAL_ERROR "frame 0 rendered on the render thread differs from the every-frame run's: ${out}")
endif()

execute_process(COMMAND ${CHECK_EXTRACT} ${WORK}/db.toml ${WORK}/run 0.005 pressure phase velocity
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT (rc EQUAL 0))
  message(FATAL_ERROR "the extract does not hold the solver's state: ${out} ${err}")
endif()

# figures: the same pictures again, from the extracts, by pvbatch.
file(RENAME ${WORK}/run/images/pressure/3d_000004.png ${WORK}/insitu_3d_000004.png)
run_poresph(0 figures ${WORK}/run --pipeline pressure)
set(figures_out "${out}")
if(NOT (EXISTS ${WORK}/run/images/pressure/3d_000004.png))
  message(FATAL_ERROR "figures did not re-render frame 4")
endif()
execute_process(COMMAND ${IMAGE_DIFF} ${WORK}/run/images/pressure/3d_000004.png ${WORK}/insitu_3d_000004.png ${WORK}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out)
if(NOT (rc EQUAL 0))
  message(FATAL_ERROR "figures' re-render differs from the in-situ image: ${out}")
endif()
if(FFMPEG)
  if(NOT (EXISTS ${WORK}/run/images/pressure/3d.mp4))
    message(FATAL_ERROR "figures assembled no MP4 though ffmpeg is installed: ${figures_out}")
  endif()
endif()

# Live with nobody listening: the run carries on.
run_poresph(0 run ${WORK}/db.toml --out ${WORK}/live --live localhost:1 --quiet)

# Bad pipeline names: exit 2, no run directory.
run_poresph(2 run ${WORK}/db.toml --out ${WORK}/bad --pipeline nosuch)
if(NOT (out MATCHES "--pipeline nosuch: no such pipeline"))
  message(FATAL_ERROR "unclear message: ${out}")
endif()
if(NOT (NOT EXISTS ${WORK}/bad))
  message(FATAL_ERROR "a run directory was left behind")
endif()

# A pipeline script that raises, on import or at a later output step: the run stops (exit 4) and
# its log names the script's Python error, rather than finish without the figures asked for.
foreach(script fails_on_import fails_later)
  run_poresph(4 run ${WORK}/db.toml --out ${WORK}/${script} --pipeline ${SRC}/tests/pipelines/${script}.py --quiet)
  file(READ ${WORK}/${script}/log.txt log)
  if(NOT (log MATCHES "pipeline script failed at [^:]+: RuntimeError: ${script}: deliberately broken"))
    message(FATAL_ERROR "the log does not name the pipeline's error: ${log}")
  endif()
endforeach()

# 2D: one view (no slab), parallel projection from the default camera, walls shown; frame 0 of a
# real 2D run against its baseline (tests/baselines/phases_2d_run.png, same threshold).
file(READ ${SRC}/cases/poiseuille_2d.toml text)
string(REPLACE "end = 0.5" "end = 0.02" text "${text}")
string(APPEND text "\n[visualisation]\ninterval = 0.01\nimage_size = [320, 240]\nevery_frame = true\n")
file(WRITE ${WORK}/p2.toml "${text}")
run_poresph(0 run ${WORK}/p2.toml --out ${WORK}/run2d --pipeline phases --quiet)
file(GLOB slabs ${WORK}/run2d/images/phases/slab_*.png)
if(slabs OR NOT (EXISTS ${WORK}/run2d/images/phases/3d_000002.png))
  message(FATAL_ERROR "2D: expected 3d_00000{0,1,2}.png and no slab images")
endif()
file(READ ${WORK}/run2d/images/visualisation.json settings)
string(JSON scale ERROR_VARIABLE no_scale GET "${settings}" camera parallel_scale)
if(no_scale)
  message(FATAL_ERROR "2D: the default camera has no parallel projection: ${settings}")
endif()
execute_process(COMMAND ${IMAGE_DIFF} ${WORK}/run2d/images/phases/3d_000000.png ${SRC}/tests/baselines/phases_2d_run.png
                        ${WORK}/run2d RESULT_VARIABLE rc OUTPUT_VARIABLE out)
if(NOT (rc EQUAL 0))
  message(FATAL_ERROR "2D frame 0 differs from tests/baselines/phases_2d_run.png: ${out} (actual and diff in ${WORK}/run2d)")
endif()

# A real cracked solid through the damage pipeline: case NAME (cases/NAME.toml) with a
# [visualisation] of INTERVAL s between frames, SIZE pixels, the camera at (0, Y, 1) looking at
# (0, Y, 0) with PARALLEL_SCALE, frame 2 against tests/baselines/BASELINE (same threshold).
function(check_cracked name interval size y scale baseline)
  file(READ ${SRC}/cases/${name}.toml text)
  string(APPEND text "\n[visualisation]\ninterval = ${interval}\nimage_size = ${size}\nscalar_bar = false\nevery_frame = true\n"
                     "[visualisation.camera]\nposition = [0.0, ${y}, 1.0]\nfocal_point = [0.0, ${y}, 0.0]\n"
                     "parallel_scale = ${scale}\n")
  file(WRITE ${WORK}/${name}.toml "${text}")
  run_poresph(0 run ${WORK}/${name}.toml --out ${WORK}/run_${name} --pipeline damage --quiet)
  execute_process(COMMAND ${IMAGE_DIFF} ${WORK}/run_${name}/images/damage/3d_000002.png ${SRC}/tests/baselines/${baseline}
                          ${WORK}/run_${name} RESULT_VARIABLE rc OUTPUT_VARIABLE out)
  if(NOT (rc EQUAL 0))
    message(FATAL_ERROR "cracked ${name} differs from tests/baselines/${baseline}: ${out} (actual and diff in ${WORK}/run_${name})")
  endif()
endfunction()

# The softening bar (Deptulski §4.2) at 3L/(2c_e), its centre cracked (D = 0.99), seen from close
# by (the intact bar of frame 1 differs from its baseline by 184).
check_cracked(softening_bar_2d 1.1095e-5 "[320, 160]" 0.004 0.012 damage_bar_run.png)
# A coupled case: the pressurised pore, confined at 1 MPa, at its end (6 ms, a pore pressure of
# 3.1 MPa): from each tip a crack of five damaged particles (D = 0.91-1) along the pore's axis
# (the intact block at 3 ms differs from its baseline by 17.2).
check_cracked(pressurised_pore_2d 3.0e-3 "[320, 320]" 0.0 0.02 damage_pore_run.png)
