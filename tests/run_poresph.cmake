# run_poresph(EXPECTED_EXIT_CODE ARGS...): runs ${PORESPH} ARGS headless (DISPLAY unset, as on a
# server) and fails the test with the exit code and output when it exits otherwise; the output
# (stdout and stderr) is left in `out`.
function(run_poresph expect_rc)
  execute_process(COMMAND ${CMAKE_COMMAND} -E env --unset=DISPLAY ${PORESPH} ${ARGN}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE o ERROR_VARIABLE e)
  if(NOT rc EQUAL expect_rc)
    message(FATAL_ERROR "poresph ${ARGN}: exit ${rc}, expected ${expect_rc}\n${o}${e}")
  endif()
  set(out "${o}${e}" PARENT_SCOPE)
endfunction()
