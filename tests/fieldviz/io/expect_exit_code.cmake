# Runs a command and passes only if it exits with EXPECTED_EXIT and its output matches
# EXPECTED_OUTPUT (a regular expression). Used to prove that a checker rejects bad input for the
# stated reason, rather than crashing (which WILL_FAIL could not tell apart).
#   cmake -DEXPECTED_EXIT=3 -DEXPECTED_OUTPUT=regex -P expect_exit_code.cmake -- command args...
foreach(var EXPECTED_EXIT EXPECTED_OUTPUT)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "expect_exit_code.cmake: -D${var}=... is required")
  endif()
endforeach()

set(command "")
set(after_separator FALSE)
math(EXPR last "${CMAKE_ARGC} - 1")
foreach(i RANGE ${last})
  if(after_separator)
    list(APPEND command "${CMAKE_ARGV${i}}")
  elseif("${CMAKE_ARGV${i}}" STREQUAL "--")
    set(after_separator TRUE)
  endif()
endforeach()
if(NOT command)
  message(FATAL_ERROR "expect_exit_code.cmake: no command after --")
endif()

execute_process(COMMAND ${command} RESULT_VARIABLE exit_code OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}")
if(NOT exit_code STREQUAL "${EXPECTED_EXIT}")
  message(FATAL_ERROR "expected exit code ${EXPECTED_EXIT}, got '${exit_code}'\nstderr:\n${err}")
endif()
if(NOT out MATCHES "${EXPECTED_OUTPUT}")
  message(FATAL_ERROR "output does not match '${EXPECTED_OUTPUT}'\nstderr:\n${err}")
endif()
message("exit code ${exit_code} and output as expected")
