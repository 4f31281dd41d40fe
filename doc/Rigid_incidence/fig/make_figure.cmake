# Copyright (c) 2026 Rigid_incidence contributors.
# SPDX-License-Identifier: LGPL-3.0-or-later
#
# Regenerates one figure of the manual: the overlap graph of a scene with its optimal
# incidence tree, from the command-line tool's --dot output, rendered to SVG by Graphviz.
#
#   cmake -DTOOL=<rigid_incidence> -DDOT=<dot> -DSCENE=<scene.json> -DOUT=<fig/name> -P make_figure.cmake
#
# writes <fig/name>.dot and <fig/name>.svg. Run by the target `doc_figures`.

foreach(v TOOL DOT SCENE OUT)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "make_figure.cmake: -D${v}=... is required")
  endif()
endforeach()

get_filename_component(scene_dir "${SCENE}" DIRECTORY)
get_filename_component(scene_file "${SCENE}" NAME)
set(raw "${OUT}.dot.tmp")
# Run from the scene's directory so that the file name in the output is the bare name.
execute_process(COMMAND "${TOOL}" analyze "${scene_file}" --dot "${raw}"
                WORKING_DIRECTORY "${scene_dir}"
                RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "make_figure.cmake: ${TOOL} analyze ${SCENE} failed (${rc}): ${err}")
endif()
file(READ "${raw}" text)
file(REMOVE "${raw}")
# write_overlap_graph_dot() (IO/write_dot.h) escapes the backslash of the "\n" line break
# in node labels, so Graphviz shows a literal "\n". Undo that here until the header is
# fixed; once it is, this replacement finds nothing and changes nothing.
string(REPLACE "\\\\n" "\\n" text "${text}")
file(WRITE "${OUT}.dot" "${text}")
execute_process(COMMAND "${DOT}" -Tsvg "${OUT}.dot" -o "${OUT}.svg"
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "make_figure.cmake: ${DOT} -Tsvg ${OUT}.dot failed (${rc}): ${err}")
endif()
message(STATUS "make_figure.cmake: wrote ${OUT}.dot and ${OUT}.svg")
