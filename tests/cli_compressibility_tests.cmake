# Weak compressibility on the command line (GUIDE §3): `check` estimates the density variation a
# case implies and says how to keep it near 1 %, `solver.compressibility = "strict"` refuses it;
# a run watches its fluid's density against solver.max_density_deviation, warns once in log.txt,
# status.json and summary.json, or stops (exit 3) with on_density_deviation = "stop".
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
set(CASE ${SRC}/cases/poiseuille_2d.toml)

function(expect_in what text)
  foreach(part IN LISTS ARGN)
    string(FIND "${text}" "${part}" pos)
    if(pos EQUAL -1)
      message(FATAL_ERROR "${what}: '${part}' not in:\n${text}")
    endif()
  endforeach()
endfunction()

# The channel at 0.01 m/s is within 1 %; at a sound speed of 5e-4 m/s its peak speed (1.25e-4 m/s)
# alone gives (v/c)^2 = 6 %.
execute_process(COMMAND ${PORESPH} check ${CASE} RESULT_VARIABLE rc OUTPUT_VARIABLE o ERROR_VARIABLE e)
expect_in("check, the channel" "${o}" "within the 1 % weak compressibility allows")
set(slow --set materials.water.sound_speed=5e-4)
execute_process(COMMAND ${PORESPH} check ${CASE} ${slow} RESULT_VARIABLE rc OUTPUT_VARIABLE o ERROR_VARIABLE e)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "check of a case past 1 % (a warning) exited ${rc}: ${o}${e}")
endif()
expect_in("check past 1 %" "${o}" "warning: ${CASE}" "materials.water.sound_speed from 0.0005 to"
          "scale the drive (materials.water.body_force) by" "Stokes flow")
execute_process(COMMAND ${PORESPH} check ${CASE} ${slow} --json RESULT_VARIABLE rc OUTPUT_VARIABLE o ERROR_VARIABLE e)
string(JSON exceeds GET "${o}" compressibility exceeds)
string(JSON estimate GET "${o}" compressibility estimate)
string(JSON needed GET "${o}" compressibility sound_speed_needed)
if(NOT rc EQUAL 0 OR NOT exceeds STREQUAL "ON" OR estimate LESS 0.05 OR estimate GREATER 0.07 OR needed LESS 0.0012)
  message(FATAL_ERROR "check --json: exit ${rc}, exceeds ${exceeds}, estimate ${estimate}, needed ${needed}\n${o}")
endif()

# Through a sphere array the pressure field that turns the flow settles in ~1.3 ms at 0.1 m/s: a
# run of 1 ms is told so, with the sound speed that settles it within a third of the run.
execute_process(COMMAND ${PORESPH} check ${SRC}/cases/sphere_array.toml --set time.end=1e-3 --json
                RESULT_VARIABLE rc OUTPUT_VARIABLE o ERROR_VARIABLE e)
string(JSON late GET "${o}" compressibility settles_late)
string(JSON settle GET "${o}" compressibility settle_time)
if(NOT rc EQUAL 0 OR NOT late STREQUAL "ON" OR settle LESS 3.4e-4)
  message(FATAL_ERROR "check --json, a short sphere-array run: exit ${rc}, settles_late ${late}, settle_time ${settle}\n${o}${e}")
endif()
execute_process(COMMAND ${PORESPH} check ${SRC}/cases/sphere_array.toml --set time.end=1e-3 RESULT_VARIABLE rc OUTPUT_VARIABLE o)
expect_in("check, a short sphere-array run" "${o}" "warning: ${SRC}/cases/sphere_array.toml: the pressure field that turns the flow settles in"
          "raise materials.water.sound_speed from 0.1 to")

# Strict: refused by check and run (exit 2), no run directory.
foreach(cmd check run)
  set(out ${WORK}/strict)
  set(extra "")
  if(cmd STREQUAL "run")
    set(extra --out ${out})
  endif()
  execute_process(COMMAND ${PORESPH} ${cmd} ${CASE} ${slow} --set solver.compressibility=strict ${extra}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE o ERROR_VARIABLE e)
  if(NOT rc EQUAL 2 OR EXISTS ${out})
    message(FATAL_ERROR "strict ${cmd}: exit ${rc} (expected 2), run directory left: ${o}${e}")
  endif()
  expect_in("strict ${cmd}" "${e}" "${CASE}" "solver.compressibility = \"strict\"" "passes 1 %")
endforeach()

# The watch: a bound the channel passes within 0.2 s warns once and the run completes.
set(out ${WORK}/watch)
execute_process(COMMAND ${PORESPH} run ${CASE} --out ${out} --quiet --set time.end=0.2
                        --set solver.max_density_deviation=1e-5 RESULT_VARIABLE rc OUTPUT_VARIABLE o ERROR_VARIABLE e)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "a run past its density bound (warn) exited ${rc}: ${o}${e}")
endif()
file(READ ${out}/log.txt log)
expect_in("log.txt" "${log}" "compressibility: estimated" "warning: the fluid's density is" "past solver.max_density_deviation"
          "(particle " "material water")
string(REGEX MATCHALL "warning: the fluid's density" once "${log}")
list(LENGTH once n)
if(NOT n EQUAL 1)
  message(FATAL_ERROR "the density warning was written ${n} times to log.txt")
endif()
file(READ ${out}/status.json status)
string(JSON warning GET "${status}" warnings 0)
expect_in("status.json" "${warning}" "the fluid's density is")
file(READ ${out}/summary.json summary)
string(JSON first GET "${summary}" density_deviation first_exceeded time)
string(JSON peak GET "${summary}" density_deviation max)
string(JSON estimate GET "${summary}" compressibility estimate)
if(NOT first GREATER 0 OR NOT peak GREATER 1e-5 OR NOT estimate GREATER 0)
  message(FATAL_ERROR "summary.json: first exceeded at ${first}, peak ${peak}, estimate ${estimate}")
endif()

# Stop instead: exit 3, status unstable with the diagnostic.
set(out ${WORK}/stop)
execute_process(COMMAND ${PORESPH} run ${CASE} --out ${out} --quiet --set time.end=0.2 --set solver.max_density_deviation=1e-5
                        --set solver.on_density_deviation=stop RESULT_VARIABLE rc OUTPUT_VARIABLE o ERROR_VARIABLE e)
file(READ ${out}/status.json status)
string(JSON state GET "${status}" state)
string(JSON diagnostic GET "${status}" diagnostic)
if(NOT rc EQUAL 3 OR NOT state STREQUAL "unstable")
  message(FATAL_ERROR "on_density_deviation = stop: exit ${rc}, state ${state}: ${diagnostic}")
endif()
expect_in("the stop's diagnostic" "${diagnostic}" "no longer weakly compressible")
message(STATUS "compressibility estimate, watch and stop: as expected")
