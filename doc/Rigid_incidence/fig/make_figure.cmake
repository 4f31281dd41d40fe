# Copyright (c) 2026 Rigid_incidence contributors.
# SPDX-License-Identifier: LGPL-3.0-or-later
#
# Regenerates one figure of the manual from the command-line tool's DOT output, rendered to
# SVG by Graphviz: with OPTION=--dot (the default) the overlap graph of a scene with its
# optimal incidence tree, with OPTION=--dot-seam the seam graph of the tree's bodies with the
# selected well-formed incidences.
#
#   cmake -DTOOL=<rigid_incidence> -DDOT=<dot> -DSCENE=<scene.json> -DOUT=<fig/name>
#         [-DOPTION=--dot|--dot-seam] -P make_figure.cmake
#
# writes <fig/name>.dot and <fig/name>.svg. Run by the target `doc_figures`.

foreach(v TOOL DOT SCENE OUT)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "make_figure.cmake: -D${v}=... is required")
  endif()
endforeach()

if(NOT DEFINED OPTION)
  set(OPTION --dot)
endif()
if(NOT OPTION STREQUAL "--dot" AND NOT OPTION STREQUAL "--dot-seam")
  message(FATAL_ERROR "make_figure.cmake: OPTION must be --dot or --dot-seam, not '${OPTION}'")
endif()

get_filename_component(scene_dir "${SCENE}" DIRECTORY)
get_filename_component(scene_file "${SCENE}" NAME)
set(raw "${OUT}.dot.tmp")
# Run from the scene's directory so that the file name in the output is the bare name.
execute_process(COMMAND "${TOOL}" analyze "${scene_file}" ${OPTION} "${raw}"
                WORKING_DIRECTORY "${scene_dir}"
                RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "make_figure.cmake: ${TOOL} analyze ${SCENE} ${OPTION} failed (${rc}): ${err}")
endif()
file(READ "${raw}" text)
file(REMOVE "${raw}")
# Safeguard: a "\n" line break in a node label whose backslash got escaped would show as a
# literal "\n" in Graphviz. The current IO/write_dot.h writes a plain "\n" (and the seam
# graph has no line breaks), so this replacement finds nothing and changes nothing.
string(REPLACE "\\\\n" "\\n" text "${text}")
file(WRITE "${OUT}.dot" "${text}")
execute_process(COMMAND "${DOT}" -Tsvg "${OUT}.dot" -o "${OUT}.svg"
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "make_figure.cmake: ${DOT} -Tsvg ${OUT}.dot failed (${rc}): ${err}")
endif()
message(STATUS "make_figure.cmake: wrote ${OUT}.dot and ${OUT}.svg")
