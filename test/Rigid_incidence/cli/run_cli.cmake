# Copyright (c) 2026 Rigid_incidence contributors.
# SPDX-License-Identifier: LGPL-3.0-or-later
#
# Runs the command-line tool once and checks what it did; used by cmake/cli.cmake as
#   cmake -DTOOL=... -DARGS=a|b|c [-D...] -P run_cli.cmake
# Variables (lists of regexes are separated by "&&", every one must match):
#   TOOL            the program to run
#   ARGS            its arguments, separated by "|"
#   EXPECT_RC       the expected exit status
#   EXPECT_STDOUT   regexes the standard output must match
#   EXPECT_STDERR   regexes the standard error must match
#   STDOUT_FILE     also write the standard output to this file
#   CHECK_PROGRAM   then run this program with CHECK_ARGS ("|"-separated; the word STDOUT_FILE is
#                   replaced by the file), which must exit 0
#   CHECK_FILE      a file the tool must have written (removed before the run) ...
#   CHECK_FILE_REGEX  ... whose content must match these regexes

if(NOT DEFINED TOOL OR NOT DEFINED EXPECT_RC)
  message(FATAL_ERROR "run_cli.cmake: TOOL and EXPECT_RC are required")
endif()
string(REPLACE "|" ";" args "${ARGS}")
if(DEFINED CHECK_FILE)
  file(REMOVE "${CHECK_FILE}")
endif()

execute_process(COMMAND "${TOOL}" ${args}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)

set(failed FALSE)
macro(fail what)
  message(SEND_ERROR "${what}")
  set(failed TRUE)
endmacro()

if(NOT "${rc}" STREQUAL "${EXPECT_RC}")
  fail("exit status ${rc}, expected ${EXPECT_RC}")
endif()

function(check_regexes stream text regexes)
  if("${regexes}" STREQUAL "")
    return()
  endif()
  string(REPLACE "&&" ";" list "${regexes}")
  foreach(rx IN LISTS list)
    if(NOT "${text}" MATCHES "${rx}")
      message(SEND_ERROR "${stream} does not match the regex '${rx}'")
      set(failed TRUE PARENT_SCOPE)
    endif()
  endforeach()
endfunction()
check_regexes("standard output" "${out}" "${EXPECT_STDOUT}")
check_regexes("standard error" "${err}" "${EXPECT_STDERR}")

if(DEFINED STDOUT_FILE)
  file(WRITE "${STDOUT_FILE}" "${out}")
endif()
if(DEFINED CHECK_PROGRAM)
  string(REPLACE "|" ";" cargs "${CHECK_ARGS}")
  string(REPLACE "STDOUT_FILE" "${STDOUT_FILE}" cargs "${cargs}")
  execute_process(COMMAND "${CHECK_PROGRAM}" ${cargs} RESULT_VARIABLE crc OUTPUT_VARIABLE cout ERROR_VARIABLE cerr)
  message(STATUS "checker: ${cout}${cerr}")
  if(NOT "${crc}" STREQUAL "0")
    fail("the checker ${CHECK_PROGRAM} failed (exit ${crc})")
  endif()
endif()
if(DEFINED CHECK_FILE)
  if(NOT EXISTS "${CHECK_FILE}")
    fail("the tool did not write ${CHECK_FILE}")
  else()
    file(READ "${CHECK_FILE}" content)
    check_regexes("${CHECK_FILE}" "${content}" "${CHECK_FILE_REGEX}")
  endif()
endif()

# Show what the tool said, to make a failure easy to read.
string(LENGTH "${out}" nout)
if(nout GREATER 2000)
  string(SUBSTRING "${out}" 0 2000 out)
  set(out "${out}...")
endif()
message(STATUS "exit status: ${rc}\n--- stdout:\n${out}\n--- stderr:\n${err}")
if(failed)
  message(FATAL_ERROR "CLI check failed: ${TOOL} ${args}")
endif()
