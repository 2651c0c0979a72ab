# Checkpoints through the real binary: a run keeps its newest checkpoints, `--restart` continues a
# run from one, bad restarts are refused before a run directory exists, and SIGINT ends a run with a
# final checkpoint.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
file(READ ${SRC}/cases/poiseuille_2d.toml base)

include(${CMAKE_CURRENT_LIST_DIR}/run_poresph.cmake)

string(REPLACE "end = 0.5" "end = 0.02" t "${base}")
file(WRITE ${WORK}/short.toml "${t}")
string(REPLACE "end = 0.5" "end = 0.04" t "${base}")
file(WRITE ${WORK}/longer.toml "${t}")

# Checkpoints every tenth of the run by default; the two newest are kept.
run_poresph(0 run ${WORK}/short.toml --out ${WORK}/first --quiet)
file(GLOB ck ${WORK}/first/checkpoints/step_*.h5)
list(LENGTH ck nck)
if(NOT nck EQUAL 2)
  message(FATAL_ERROR "expected the 2 newest checkpoints, found ${nck}: ${ck}")
endif()

# Continue the finished run to a later end time.
run_poresph(0 run ${WORK}/longer.toml --restart ${WORK}/first --out ${WORK}/continued --quiet)
file(READ ${WORK}/continued/log.txt log)
if(NOT log MATCHES "restarted from .*first/checkpoints/step_[0-9]+\\.h5 at t = 0\\.02")
  message(FATAL_ERROR "the continued run's log does not say where it restarted: ${log}")
endif()
file(READ ${WORK}/continued/summary.json summary)
if(NOT summary MATCHES "\"status\": \"completed\"" OR NOT summary MATCHES "\"time\": 0\\.04")
  message(FATAL_ERROR "continued run summary: ${summary}")
endif()

# Refused: nothing left to run, no checkpoint there, another scene, a damaged file.
run_poresph(2 run ${WORK}/short.toml --restart ${WORK}/first --out ${WORK}/bad1)
if(NOT out MATCHES "raise time.end")
  message(FATAL_ERROR "restart past the end: ${out}")
endif()
file(MAKE_DIRECTORY ${WORK}/empty)
run_poresph(2 run ${WORK}/longer.toml --restart ${WORK}/empty --out ${WORK}/bad2)
if(NOT out MATCHES "no intact checkpoint")
  message(FATAL_ERROR "restart from a directory without checkpoints: ${out}")
endif()
string(REPLACE "spacing = 5.0e-5" "spacing = 2.5e-5" t "${t}")
file(WRITE ${WORK}/finer.toml "${t}")
run_poresph(2 run ${WORK}/finer.toml --restart ${WORK}/first --out ${WORK}/bad3)
if(NOT out MATCHES "particle count")
  message(FATAL_ERROR "restart of another scene: ${out}")
endif()
file(WRITE ${WORK}/damaged.ckpt "PORESPH-CHECKPOINT 1\n{}\n")
run_poresph(2 run ${WORK}/longer.toml --restart ${WORK}/damaged.ckpt --out ${WORK}/bad4)
if(NOT out MATCHES "damaged.ckpt: damaged checkpoint header")
  message(FATAL_ERROR "restart from a damaged file: ${out}")
endif()
foreach(d bad1 bad2 bad3 bad4)
  if(EXISTS ${WORK}/${d})
    message(FATAL_ERROR "a refused restart left the run directory ${d} behind")
  endif()
endforeach()

# A restart from a directory whose newest checkpoint is damaged (cut short) starts from the newest
# intact one and says so; a stale .partial (a write cut short by a kill) is removed.
file(COPY ${WORK}/first/ DESTINATION ${WORK}/damaged_run)
file(GLOB ck ${WORK}/damaged_run/checkpoints/step_*.h5)
list(SORT ck)
list(GET ck 1 newest)
execute_process(COMMAND truncate -s 2000 ${newest})  # (a binary file: not through a CMake string)
file(WRITE ${WORK}/damaged_run/checkpoints/step_0000099999.h5.partial "half a checkpoint")
run_poresph(0 run ${WORK}/longer.toml --restart ${WORK}/damaged_run --out ${WORK}/fell_back --quiet)
file(READ ${WORK}/fell_back/log.txt log)
list(GET ck 0 older)
if(NOT log MATCHES "skipped a damaged checkpoint: [^\n]*damaged or truncated HDF5 file" OR NOT log MATCHES "restarted from ${older}"
   OR NOT log MATCHES "removed [^\n]*step_0000099999.h5.partial")
  message(FATAL_ERROR "restart past a damaged newest checkpoint: ${log}")
endif()
if(EXISTS ${WORK}/damaged_run/checkpoints/step_0000099999.h5.partial)
  message(FATAL_ERROR "the stale .partial checkpoint was not removed")
endif()

# SIGINT: the run ends cleanly with a final checkpoint (exit 130).
string(REPLACE "end = 0.5" "end = 1000.0" t "${base}")
file(WRITE ${WORK}/endless.toml "${t}")
execute_process(COMMAND timeout --preserve-status -s INT 3 ${PORESPH} run ${WORK}/endless.toml --out ${WORK}/stopped --quiet
                RESULT_VARIABLE rc OUTPUT_VARIABLE o ERROR_VARIABLE e)
if(NOT rc EQUAL 130)
  message(FATAL_ERROR "an interrupted run exited ${rc}, expected 130: ${o}${e}")
endif()
file(READ ${WORK}/stopped/summary.json summary)
file(GLOB ck ${WORK}/stopped/checkpoints/step_*.h5)
if(NOT summary MATCHES "\"status\": \"interrupted\"" OR NOT ck)
  message(FATAL_ERROR "interrupted run: no final checkpoint or status (${ck}): ${summary}")
endif()
message(STATUS "checkpoint command-line tests passed")
