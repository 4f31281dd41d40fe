# Copyright (c) 2026 Rigid_incidence contributors.
# SPDX-License-Identifier: LGPL-3.0-or-later
#
# Runs Doxygen and reports its warning log.
#
#   cmake -DDOXYGEN=<doxygen> -DDOXYFILE=<Doxyfile> -DWARN_LOG=<its WARN_LOGFILE>
#         [-DFAIL_ON_WARNINGS=ON] -P run_doxygen.cmake
#
# Fails if Doxygen fails, if the log is missing, or (with FAIL_ON_WARNINGS) if the log is
# not empty; the warnings are printed either way.

foreach(v DOXYGEN DOXYFILE WARN_LOG)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "run_doxygen.cmake: -D${v}=... is required")
  endif()
endforeach()

file(REMOVE "${WARN_LOG}")
get_filename_component(log_dir "${WARN_LOG}" DIRECTORY)
file(MAKE_DIRECTORY "${log_dir}")

execute_process(COMMAND "${DOXYGEN}" "${DOXYFILE}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "doxygen ${DOXYFILE} failed (exit status ${rc}):\n${out}${err}")
endif()
if(NOT EXISTS "${WARN_LOG}")
  message(FATAL_ERROR "doxygen wrote no warning log ${WARN_LOG}: is WARN_LOGFILE set in ${DOXYFILE}?")
endif()

file(READ "${WARN_LOG}" warnings)
string(STRIP "${warnings}" warnings)
if(warnings STREQUAL "")
  message(STATUS "doxygen: no warnings")
  return()
endif()
string(REGEX MATCHALL "\n" newlines "${warnings}")
list(LENGTH newlines n)
math(EXPR n "${n} + 1")
# Print the log as it is (message() would re-wrap its lines).
execute_process(COMMAND "${CMAKE_COMMAND}" -E echo "${warnings}")
if(FAIL_ON_WARNINGS)
  message(FATAL_ERROR "doxygen: ${n} warning line(s), listed above (log: ${WARN_LOG})")
else()
  message(WARNING "doxygen: ${n} warning line(s), listed above (log: ${WARN_LOG})")
endif()
