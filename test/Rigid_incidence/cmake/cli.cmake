# Copyright (c) 2026 Rigid_incidence contributors.
# SPDX-License-Identifier: LGPL-3.0-or-later
#
# Tests of the command-line tool `rigid_incidence` (each runs cli/run_cli.cmake, which runs the
# tool and checks its exit status and output):
#  - cli_malformed_<case>: every file of data/malformed/ is refused with exit status 2 and a
#    message "rigid_incidence: error: <file>: ..." naming the fault (regexes of the table below,
#    separated by "&&", all must match standard error);
#  - cli_help, cli_usage_*: --help lists every command and option; usage errors exit 1;
#  - cli_json_<scene>_<kernel>: `analyze SCENE --json` prints JSON checked by cli_json_check
#    (structure, self-consistency, and the paper's numbers for tetra, tetra_i, quad, pent);
#  - cli_dot: --dot FILE writes a Graphviz file "graph overlap ...";
#  - cli_scene_<scene>_<kernel>: every shipped scene analyzes with exit 0 under every kernel.
# The files of data/malformed/ are written by `test_read_scene --write-malformed DIR`, which
# prints this table.

# One test per (case, regex) pair of the list named `table`: `COMMAND DIR/case.json` exits
# with RC and its STREAM (STDOUT or STDERR) matches PREFIX (where @CASE@ is the case) and the regex.
function(_ri_table prefix command dir rc stream rx_prefix table)
  set(_t ${${table}})
  list(LENGTH _t _n)
  math(EXPR _last "${_n} - 1")
  foreach(_i RANGE 0 ${_last} 2)
    math(EXPR _j "${_i} + 1")
    list(GET _t ${_i} _case)
    list(GET _t ${_j} _rx)
    string(REPLACE "@CASE@" "${_case}" _p "${rx_prefix}")
    # a missing file fails its test ("cannot open")
    add_test(NAME ${prefix}${_case} COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=${command}|${dir}/${_case}.json"
             -DEXPECT_RC=${rc} "-DEXPECT_${stream}=${_p}${_rx}" -P ${_ri_cli_script})
  endforeach()
endfunction()

if(TARGET rigid_incidence)
  set(_ri_cli_script ${CMAKE_CURRENT_LIST_DIR}/../cli/run_cli.cmake)
  set(_ri_malformed_dir ${CMAKE_CURRENT_LIST_DIR}/../data/malformed)
  set(_ri_tool $<TARGET_FILE:rigid_incidence>)

  # case  regexes on standard error (besides the file name)
  set(_ri_malformed_table
  json_empty "invalid JSON"
  json_whitespace_only "invalid JSON"
  json_truncated "invalid JSON"
  json_truncated_in_number "invalid JSON"
  json_trailing_garbage "invalid JSON"
  json_trailing_brace "invalid JSON"
  json_two_values "invalid JSON"
  json_missing_comma "invalid JSON"
  json_trailing_comma "invalid JSON"
  json_single_quotes "invalid JSON"
  json_unterminated_string "invalid JSON"
  json_comment "invalid JSON"
  json_bare_word "invalid JSON"
  json_nan_literal "invalid JSON"
  json_infinity_literal "invalid JSON"
  json_control_char_in_string "invalid JSON"
  json_deep_arrays "(nest|deep)"
  json_deep_inside_scene "(nest|deep)"
  top_level_array "object"
  format_unknown "format&&rigid-incidence-scene/2"
  format_missing "format"
  format_not_string "format"
  format_duplicate "format&&duplicate"
  unknown_top_field "bodys"
  free_distance_unknown_point "free_distance&&'Q' is in no body"
  inequality_three_points "inequalities.0.&&4 point labels"
  unknown_body_field "colour&&('c2'|bodies.1.)"
  unknown_distance_field "weight&&distances.0."
  bodies_missing "bodies"
  bodies_empty "bodies"
  bodies_not_array "bodies"
  body_missing_name "bodies.1.&&name"
  body_empty_name "(bodies.1.|body '')&&name"
  body_points_missing "'c2'&&points"
  body_points_array "'c2'&&points"
  coordinates_missing "'c2'&&'D'&&coordinate"
  coordinates_null "'c2'&&'D'"
  coordinates_object "'c2'&&'D'"
  coordinates_two "'c2'&&'D'&&coordinate"
  coordinates_four "'c2'&&'D'&&coordinate"
  coordinate_non_numeric "'c2'&&'D'&&coordinate y"
  coordinate_boolean "'c2'&&'D'&&coordinate z"
  coordinate_null "'c2'&&'D'&&coordinate x"
  coordinate_array "'c2'&&'D'&&coordinate x"
  coordinate_empty_string "'c2'&&'D'&&coordinate x"
  coordinate_nan "'c2'&&'D'&&coordinate x&&NaN"
  coordinate_nan_lowercase "'c2'&&'D'&&coordinate y&&NaN"
  coordinate_inf "'c2'&&'D'&&coordinate z&&infinite"
  coordinate_minus_infinity "'c2'&&'D'&&coordinate x&&infinite"
  coordinate_huge_exponent "'c2'&&'D'&&coordinate x&&exponent"
  coordinate_hex "'c2'&&'D'&&coordinate x"
  coordinate_zero_denominator "'c2'&&'D'&&coordinate x"
  coordinate_inner_space "'c2'&&'D'&&coordinate x"
  coordinate_trailing_point "'c2'&&'D'&&coordinate x"
  body_duplicate_name "'c1'&&duplicate"
  label_duplicate "'c2'&&'A'&&duplicate"
  label_empty "'c2'&&label"
  body_one_point "'c2'&&2 points"
  body_no_points "'c2'&&2 points"
  points_coincident "'c2'&&'D'&&'E'&&coincide"
  points_coincident_rational_decimal "'c2'&&'D'&&'E'&&coincide"
  points_coincident_plain_number "'c2'&&'D'&&'E'&&coincide"
  distance_unknown_label "distances.0.&&'Z'"
  distance_squared_negative "distances.0.&&squared&&positive"
  distance_length_negative "distances.0.&&length&&positive"
  distance_nan "distances.0.&&squared&&NaN"
  distance_infinite "distances.0.&&length&&infinite"
  distance_non_numeric "distances.0.&&squared"
  distance_same_point "distances.0.&&'B'"
  distance_both_values "distances.0.&&squared&&length"
  distance_no_value "distances.0.&&(squared|length)"
  distance_one_label "distances.0.&&between"
  distance_labels_not_strings "distances.0.&&between"
  distance_disagree "distances.1.&&distances.0.&&'B'&&'D'"
  distance_disagree_reversed "distances.1.&&distances.0.&&'B'&&'D'"
  frame_unknown "frame&&c9"
  frame_not_string "frame"
  distance_inside_body_disagrees "'c1'&&'B'&&'C'&&distances.0."
  shared_points_disagree_subset "'c1'&&'c2'&&'A'&&'B'"
  shared_points_disagree_merge "'c1'&&'c2'&&'A'&&'B'"
  shared_points_disagree_two "'c1'&&'c2'&&'A'&&'B'"
  mirror_bodies "'c1'&&'c2'&&mirror"
  mirror_body_inside "'c1'&&'c2'&&mirror"
  )

  _ri_table(cli_malformed_ analyze ${_ri_malformed_dir} 2 STDERR "^rigid_incidence: error: [^\n]*@CASE@\\.json: &&" _ri_malformed_table)
  # well formed, but without a real configuration (decided exactly): `solve` answers
  # "0 configurations, complete" with exit status 0 and names the points and distances
  # (issue 27, item 5; these files are written with the malformed ones)
  set(_ri_no_configuration_table
  implied_triangle_inequality "no real configuration&&'A'&&'B'&&'C'&&triangle inequality&&0 configuration\\(s\\), all certified: complete"
  )
  _ri_table(cli_no_configuration_ solve ${_ri_malformed_dir} 0 STDOUT "" _ri_no_configuration_table)
  # a distance of 0 is a coincidence: its two labels name one point (issue 27, item 5)
  set(_ri_coincidence_dir ${CMAKE_CURRENT_LIST_DIR}/../data/coincidence)
  foreach(_case distance_squared_zero distance_squared_zero_rational distance_length_zero)
    add_test(NAME cli_coincidence_${_case}
             COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=analyze|${_ri_coincidence_dir}/${_case}.json" -DEXPECT_RC=0
                     "-DEXPECT_STDOUT='D' and 'B' are one point, 'B' \\(distances.0. \\('B'-'D'\\) is 0\\)" -P ${_ri_cli_script})
  endforeach()
  set(_ri_coincidence_solve_table
    coincidence_hinge "'K1' and 'H1' are one point&&'K2' and 'H2' are one point&&2 configuration\\(s\\), all certified: complete&&K1 = &&K2 = "
    coincidence_apart "no real configuration&&body 'A' holds 'R'&&'P'&&0 configuration\\(s\\), all certified: complete")
  _ri_table(cli_ solve ${_ri_coincidence_dir} 0 STDOUT "" _ri_coincidence_solve_table)
  # issue 27, item 7: --kernel epeck reads exactly (it rounded to doubles, then refused the
  # hinge: "squared 0.25000000000000011 vs 0.25"); item 6: a frame point at 1e308 alone does
  # not scale the scene (it did, by 2^-1023, and the hinge came out incomplete)
  set(_ri_data ${CMAKE_CURRENT_LIST_DIR}/../data)
  foreach(_k exact epick epeck)
    add_test(NAME cli_solve_decimal_hinge_${_k}
             COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve|${_ri_data}/decimal_hinge.json|--kernel|${_k}" -DEXPECT_RC=0
                     "-DEXPECT_STDOUT=2 configuration\\(s\\), all certified: complete" -P ${_ri_cli_script})
  endforeach()
  add_test(NAME cli_solve_hinge_far_frame_point
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve|${_ri_data}/hinge_far_frame_point.json" -DEXPECT_RC=0
                   "-DEXPECT_STDOUT=2 configuration\\(s\\), all certified: complete&&F = \\(1e\\+308, 0, 0\\)" -P ${_ri_cli_script})
  # every file of the directory must be in a table: a file without a line gets a failing test
  file(GLOB _files RELATIVE ${_ri_malformed_dir} ${_ri_malformed_dir}/*.json)
  foreach(_f ${_files})
    string(REGEX REPLACE "\\.json$" "" _case ${_f})
    list(FIND _ri_malformed_table ${_case} _at)
    if(_at EQUAL -1)
      list(FIND _ri_no_configuration_table ${_case} _at)
    endif()
    if(_at EQUAL -1)
      message(WARNING "cli.cmake: data/malformed/${_f} has no line in the table")
      add_test(NAME cli_malformed_${_case}_not_in_table COMMAND ${CMAKE_COMMAND} -E false)
    endif()
  endforeach()

  # --- usage
  add_test(NAME cli_help COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=--help" -DEXPECT_RC=0
           "-DEXPECT_STDOUT=analyze&&--json&&--dot&&--kernel&&exact&&epick&&epeck&&--help" -P ${_ri_cli_script})
  add_test(NAME cli_help_after_analyze COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=analyze|--help" -DEXPECT_RC=0
           "-DEXPECT_STDOUT=analyze&&--json&&--dot&&--kernel" -P ${_ri_cli_script})
  add_test(NAME cli_usage_no_arguments COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=" -DEXPECT_RC=1
           "-DEXPECT_STDERR=analyze" -P ${_ri_cli_script})
  add_test(NAME cli_usage_unknown_option
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=analyze|${RIGID_INCIDENCE_DATA_DIR}/tetra.json|--frobnicate"
                   -DEXPECT_RC=1 "-DEXPECT_STDERR=--frobnicate" -P ${_ri_cli_script})
  add_test(NAME cli_usage_unknown_command COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=analyse|x.json" -DEXPECT_RC=1
           "-DEXPECT_STDERR=analyse" -P ${_ri_cli_script})
  add_test(NAME cli_usage_unknown_kernel
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=analyze|${RIGID_INCIDENCE_DATA_DIR}/tetra.json|--kernel|float"
                   -DEXPECT_RC=1 "-DEXPECT_STDERR=float" -P ${_ri_cli_script})
  add_test(NAME cli_usage_kernel_without_value
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=analyze|${RIGID_INCIDENCE_DATA_DIR}/tetra.json|--kernel"
                   -DEXPECT_RC=1 "-DEXPECT_STDERR=--kernel" -P ${_ri_cli_script})
  add_test(NAME cli_usage_no_scene COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=analyze|--json" -DEXPECT_RC=1
           -P ${_ri_cli_script})
  add_test(NAME cli_usage_two_scenes
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}"
                   "-DARGS=analyze|${RIGID_INCIDENCE_DATA_DIR}/tetra.json|${RIGID_INCIDENCE_DATA_DIR}/quad.json"
                   -DEXPECT_RC=1 "-DEXPECT_STDERR=quad.json" -P ${_ri_cli_script})
  add_test(NAME cli_missing_file
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=analyze|${CMAKE_CURRENT_BINARY_DIR}/no_such_scene.json"
                   -DEXPECT_RC=2 "-DEXPECT_STDERR=^rigid_incidence: error: [^\n]*no_such_scene\\.json" -P ${_ri_cli_script})

  # --- --json, checked by a small program
  add_executable(cli_json_check ${CMAKE_CURRENT_LIST_DIR}/../cli_json_check.cpp)
  ri_test_flags(cli_json_check)
  target_link_libraries(cli_json_check PRIVATE nlohmann_json::nlohmann_json)
  set(_ri_expect_tetra "--bodies|7|--implied|4|--weight|3|--depth-sum|3|--root|I1{P12,P23,P31}|--reduced|3|--naive|12|--covering|4|--well-formed|15|--remaining|0|--equations|3|--body-distances|3|--conflicts|0|--generic-dof|0")
  # naive_variables = 6(k-1) over the k bodies of the scene (3 for tetra: 12), as the tool defines
  # it since commit f92bedc; over the covering set (Section 4.2 of the paper) it would be 18.
  set(_ri_expect_tetra_i "${_ri_expect_tetra}")
  set(_ri_expect_quad "--bodies|9|--weight|4|--depth-sum|4|--root|c5|--reduced|4|--naive|24|--well-formed|20|--remaining|0|--equations|4|--conflicts|0|--generic-dof|0")
  set(_ri_expect_pent "--bodies|6|--weight|4|--depth-sum|6|--root|c5|--ties|6|--reduced|4|--naive|24|--well-formed|23|--remaining|3|--equations|4|--conflicts|0|--generic-dof|0")
  # over-constrained: a ring of four hinges (rdof 20 > 18), two distances of c4 in conflict
  set(_ri_expect_hinge_ring "--weight|2|--reduced|2|--equations|2|--body-distances|2|--conflicts|2|--generic-dof|0")
  # a free point: the bar's far end E (3 variables), held by one distance: 2 dof
  set(_ri_expect_bar_end "--weight|1|--reduced|4|--equations|2|--conflicts|0|--generic-dof|2")

  file(GLOB _scenes ${RIGID_INCIDENCE_DATA_DIR}/*.json)
  foreach(_scene ${_scenes})
    get_filename_component(_s ${_scene} NAME_WE)
    foreach(_k exact epick epeck)
      add_test(NAME cli_scene_${_s}_${_k}
               COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=analyze|${_scene}|--kernel|${_k}" -DEXPECT_RC=0
                       "-DEXPECT_STDOUT=optimal incidence tree" -P ${_ri_cli_script})
      set(_expect "")
      if(DEFINED _ri_expect_${_s})
        set(_expect "|${_ri_expect_${_s}}")
      endif()
      add_test(NAME cli_json_${_s}_${_k}
               COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=analyze|${_scene}|--kernel|${_k}|--json" -DEXPECT_RC=0
                       "-DSTDOUT_FILE=${CMAKE_CURRENT_BINARY_DIR}/cli_json_${_s}_${_k}.json"
                       "-DCHECK_PROGRAM=$<TARGET_FILE:cli_json_check>" "-DCHECK_ARGS=STDOUT_FILE${_expect}"
                       -P ${_ri_cli_script})
    endforeach()
  endforeach()

  # --- --dot FILE
  add_test(NAME cli_dot
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}"
                   "-DARGS=analyze|${RIGID_INCIDENCE_DATA_DIR}/tetra.json|--dot|${CMAKE_CURRENT_BINARY_DIR}/cli_tetra.dot"
                   -DEXPECT_RC=0 "-DCHECK_FILE=${CMAKE_CURRENT_BINARY_DIR}/cli_tetra.dot"
                   "-DCHECK_FILE_REGEX=^graph overlap&&c1&&I1{P12,P23,P31}&&}[ \t\r\n]*$" -P ${_ri_cli_script})
  # --dot-seam FILE writes the seam graph with the seam tree (three coordinates) highlighted
  add_test(NAME cli_dot_seam
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}"
                   "-DARGS=analyze|${RIGID_INCIDENCE_DATA_DIR}/pent.json|--dot-seam|${CMAKE_CURRENT_BINARY_DIR}/cli_pent_seam.dot"
                   -DEXPECT_RC=0 "-DCHECK_FILE=${CMAKE_CURRENT_BINARY_DIR}/cli_pent_seam.dot"
                   "-DCHECK_FILE_REGEX=^graph seam&&cluster_b&&1,2,3&&23 well-formed incidences&&}[ \t\r\n]*$" -P ${_ri_cli_script})
endif()

# --- reduce: the reduced system (issue 5)
if(TARGET rigid_incidence)
  set(_ri_d ${RIGID_INCIDENCE_DATA_DIR})
  add_test(NAME cli_reduce_tetra
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=reduce|${_ri_d}/tetra.json" -DEXPECT_RC=0
                   "-DEXPECT_STDOUT=interval coefficients[^\n]*: 3 variables, 3 equations" -P ${_ri_cli_script})
  add_test(NAME cli_reduce_quad_exact
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=reduce|${_ri_d}/quad.json|--chart|1,0,1,0" -DEXPECT_RC=0
                   "-DEXPECT_STDOUT=exact coefficients[^\n]*: 4 variables, 4 equations" -P ${_ri_cli_script})
  add_test(NAME cli_reduce_pent_json
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=reduce|${_ri_d}/pent.json|--json" -DEXPECT_RC=0
                   "-DEXPECT_STDOUT=\"chart_combinations\": 16,[^$]*\"square\": true" -P ${_ri_cli_script})
  # the work of a full solve, before it runs (issue 28, item 5); test_scene_solve_work checks
  # the numbers against the solve itself
  add_test(NAME cli_reduce_work
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=reduce|${_ri_d}/tetra.json" -DEXPECT_RC=0
                   "-DEXPECT_STDOUT=work of a full solve: 8 chart combinations x 1 placement combination = 8 reduced systems at most; 3 equations in 3 variables: 1 block \\(largest: 3 variables\\), 1 independent part"
                   -P ${_ri_cli_script})
  add_test(NAME cli_analyze_work_json
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=analyze|${_ri_d}/bar_end.json|--json" -DEXPECT_RC=0
                   "-DEXPECT_STDOUT=\"work\": {[^}]*\"chart_combinations\": 2,[^}]*\"systems\": 2,[^}]*\"independent_parts\": 1"
                   -P ${_ri_cli_script})
  add_test(NAME cli_reduce_stereographic
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=reduce|${_ri_d}/pent.json|--form|stereographic" -DEXPECT_RC=0
                   "-DEXPECT_STDOUT=stereographic form[^\n]*: 4 variables, 4 equations" -P ${_ri_cli_script})
  add_test(NAME cli_reduce_under_constrained
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=reduce|${_ri_d}/bar_end.json" -DEXPECT_RC=0
                   "-DEXPECT_STDOUT=note: 2 equation\\(s\\) fewer than variables" -P ${_ri_cli_script})
  add_test(NAME cli_reduce_bad_chart
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=reduce|${_ri_d}/tetra.json|--chart|0,2,0" -DEXPECT_RC=2
                   "-DEXPECT_STDERR=chart 2 of tree edge 1 \\('I1\\{P12,P23,P31\\}' -> 'c2'\\), which has 2" -P ${_ri_cli_script})
  add_test(NAME cli_reduce_chart_count
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=reduce|${_ri_d}/tetra.json|--chart|0,1" -DEXPECT_RC=2
                   "-DEXPECT_STDERR=2 chart indices for 3 tree edges" -P ${_ri_cli_script})
  add_test(NAME cli_reduce_chart_syntax
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=reduce|${_ri_d}/tetra.json|--chart|0,x,1" -DEXPECT_RC=2
                   "-DEXPECT_STDERR=--chart: 'x' is not a chart index" -P ${_ri_cli_script})
  add_test(NAME cli_reduce_exact_needs_coordinates
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=reduce|${_ri_d}/tetra.json|--coefficients|exact" -DEXPECT_RC=2
                   "-DEXPECT_STDERR=body 'I1\\{P12,P23,P31\\}' is known by distances" -P ${_ri_cli_script})
  add_test(NAME cli_reduce_over_constrained
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=reduce|${_ri_d}/hinge_ring.json|--json" -DEXPECT_RC=0
                   "-DEXPECT_STDOUT=\"left_out\": \\[[^]]*distance[^]]*distance[^]]*\\],[^$]*\"square\": false" -P ${_ri_cli_script})
  # two bodies outside the covering set fix the same pair: one constraint, not a conflict
  # (the benchmark's random10-s0 once reported it as over-constrained)
  add_test(NAME cli_reduce_duplicate_body_distance
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}"
                   "-DARGS=reduce|${CMAKE_CURRENT_LIST_DIR}/../data/duplicate_body_distance.json|--json" -DEXPECT_RC=0
                   "-DEXPECT_STDOUT=\"left_out\": \\[\\],[^$]*\"square\": true" -P ${_ri_cli_script})
  add_test(NAME cli_reduce_rejects_dot
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=reduce|${_ri_d}/tetra.json|--dot|x.dot" -DEXPECT_RC=1
                   "-DEXPECT_STDERR=--dot is an option of analyze" -P ${_ri_cli_script})
  add_test(NAME cli_analyze_rejects_chart
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=analyze|${_ri_d}/tetra.json|--chart|0" -DEXPECT_RC=1
                   "-DEXPECT_STDERR=--chart is an option of reduce" -P ${_ri_cli_script})
endif()

# --- solve: every real configuration (issue 6). Each solution is checked by solve_json_check
# against the scene file alone (rigid bodies, distances, shared labels, printed poses); the
# expected counts are the papers' (tetra ii: 4, pent iv: 8) or an independent count (see
# examples/Rigid_incidence/data/README.md).
if(TARGET rigid_incidence)
  add_executable(solve_json_check ${CMAKE_CURRENT_LIST_DIR}/../solve_json_check.cpp)
  ri_test_flags(solve_json_check)
  target_link_libraries(solve_json_check PRIVATE nlohmann_json::nlohmann_json)
  set(_ri_d ${RIGID_INCIDENCE_DATA_DIR})
  # scene  expectations
  set(_ri_solve_table
    tetra "--solutions|4|--certified|4|--complete|true"
    tetra_ii "--solutions|4|--certified|4|--complete|true"
    pent "--solutions|8|--certified|8|--complete|true"
    tetra_iii "--solutions|12|--certified|12|--complete|true"
    pent_iv "--solutions|8|--certified|8|--complete|true"
    quad_distinct "--solutions|16|--certified|16|--complete|true"
    body_distance_through_placement "--solutions|8|--certified|8|--complete|true"
    implied_body_order "--solutions|1|--certified|1|--complete|true"
    hinge_three_point_axis "--solutions|4|--certified|4|--complete|true"
    flat_hinges "--solutions|1|--certified|1|--singular|1|--complete|true"
    rail_point_by_distances "--solutions|32|--certified|32|--singular|0|--complete|true"
    rail_point_on_body_line "--solutions|32|--certified|32|--singular|32|--complete|true"
    rail_points_on_two_bodies "--solutions|2|--certified|2|--singular|2|--complete|true"
    flat_implied_body "--solutions|4|--certified|4|--singular|4|--complete|true"
    tetra_ineq "--solutions|2|--certified|2|--complete|true"
    tetra_i "--solutions|2|--certified|2|--complete|true|--distinct|1e-17|--coefficient-precision-at-least|128"
    tetra_i_tangent "--solutions|2|--certified|2|--complete|true|--distinct|1e-17|--coefficient-precision-at-least|128"
    quad_collinear "--solutions|2|--certified|0|--singular|2|--complete|false"
    quad "--complete|false|--diagnosis|positive_dimensional"
    quad_symmetric "--complete|false|--diagnosis|positive_dimensional")
  list(LENGTH _ri_solve_table _n)
  math(EXPR _last "${_n} - 1")
  foreach(_i RANGE 0 ${_last} 2)
    math(EXPR _j "${_i} + 1")
    list(GET _ri_solve_table ${_i} _s)
    list(GET _ri_solve_table ${_j} _expect)
    add_test(NAME cli_solve_${_s}
             COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve|${_ri_d}/${_s}.json|--json" -DEXPECT_RC=0
                     "-DSTDOUT_FILE=${CMAKE_CURRENT_BINARY_DIR}/cli_solve_${_s}.json"
                     "-DCHECK_PROGRAM=$<TARGET_FILE:solve_json_check>" "-DCHECK_ARGS=STDOUT_FILE|${_ri_d}/${_s}.json|${_expect}"
                     -P ${_ri_cli_script})
  endforeach()
  # the flagship: 40 real assembly modes (about 15 s in Release; not in the sanitizer build,
  # where it would take minutes: the sanitizers see the same code on the smaller scenes)
  if(NOT RIGID_INCIDENCE_SANITIZE)
    add_test(NAME cli_solve_stewart_gough40
             COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve|${_ri_d}/stewart_gough40.json|--json" -DEXPECT_RC=0
                     "-DSTDOUT_FILE=${CMAKE_CURRENT_BINARY_DIR}/cli_solve_stewart_gough40.json"
                     "-DCHECK_PROGRAM=$<TARGET_FILE:solve_json_check>"
                     "-DCHECK_ARGS=STDOUT_FILE|${_ri_d}/stewart_gough40.json|--solutions|40|--certified|40|--complete|true"
                     -P ${_ri_cli_script})
  endif()
  # two stacked Stewart-Gough platforms (issue 28, items 1 and 6): solved along the reduced
  # system's solution plan, 2 blocks of 6 variables, complete and certified; --no-plan solves
  # the whole system of 12 (each plate's legs in its own 6 variables: the path of plates is the
  # optimal tree), far slower: a time limit of 3 s cuts it, and the answer says so
  set(_ri_platforms ${CMAKE_CURRENT_LIST_DIR}/../data/platforms2.json)
  add_test(NAME cli_solve_platforms2
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve|${_ri_platforms}|--json" -DEXPECT_RC=0
                   "-DEXPECT_STDOUT=\"planned_systems\": 16"
                   "-DSTDOUT_FILE=${CMAKE_CURRENT_BINARY_DIR}/cli_solve_platforms2.json"
                   "-DCHECK_PROGRAM=$<TARGET_FILE:solve_json_check>"
                   "-DCHECK_ARGS=STDOUT_FILE|${_ri_platforms}|--complete|true"
                   -P ${_ri_cli_script})
  # the factored answer (issue 28, item 1): one part per plate, the count exact (6 x 6) when
  # the list is cut at 3, the answer complete all the same; --max-listed takes whole numbers
  add_test(NAME cli_solve_platforms2_listed
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve|${_ri_platforms}|--json|--max-listed|3" -DEXPECT_RC=0
                   "-DEXPECT_STDOUT=\"configuration_count\": 36&&\"listing\": \"3 of 36 configurations listed"
                   "-DSTDOUT_FILE=${CMAKE_CURRENT_BINARY_DIR}/cli_solve_platforms2_listed.json"
                   "-DCHECK_PROGRAM=$<TARGET_FILE:solve_json_check>"
                   "-DCHECK_ARGS=STDOUT_FILE|${_ri_platforms}|--complete|true|--solutions|3|--count|36"
                   -P ${_ri_cli_script})
  add_test(NAME cli_solve_platforms2_text_parts
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve|${_ri_platforms}|--max-listed|2" -DEXPECT_RC=0
                   "-DEXPECT_STDOUT=6 solution\\(s\\) of the part placing&&36 configuration\\(s\\), all certified: complete&&listed: 2 of 36"
                   -P ${_ri_cli_script})
  # the charts chosen by propagation along the tree of hinges (with arc consistency first: 15
  # of 16 combinations never built, 4 without), and --no-propagation (every combination built:
  # the same configurations)
  add_test(NAME cli_solve_chain5_propagation
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve|${CMAKE_CURRENT_LIST_DIR}/../data/chain5.json" -DEXPECT_RC=0
                   "-DEXPECT_STDOUT=15 chart combinations never built \\(excluded by propagation" -P ${_ri_cli_script})
  add_test(NAME cli_solve_chain5_no_propagation
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve|${CMAKE_CURRENT_LIST_DIR}/../data/chain5.json|--no-propagation|--json" -DEXPECT_RC=0
                   "-DEXPECT_STDOUT=\"excluded_by_propagation\": 0,"
                   "-DSTDOUT_FILE=${CMAKE_CURRENT_BINARY_DIR}/cli_solve_chain5_no_propagation.json"
                   "-DCHECK_PROGRAM=$<TARGET_FILE:solve_json_check>"
                   "-DCHECK_ARGS=STDOUT_FILE|${CMAKE_CURRENT_LIST_DIR}/../data/chain5.json|--complete|true|--solutions|2"
                   -P ${_ri_cli_script})
  # the chain of 7 (64 chart combinations) swept along its tree, with and without arc
  # consistency: the same 2 configurations, complete
  foreach(_ri_consistency IN ITEMS on off)
    set(_ri_extra "")
    set(_ri_kept "\"consistency\": \\{")
    if(_ri_consistency STREQUAL "off")
      set(_ri_extra "|--no-consistency")
      set(_ri_kept "\"consistency\": null")
    endif()
    add_test(NAME cli_solve_chain7_consistency_${_ri_consistency}
             COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve|${CMAKE_CURRENT_LIST_DIR}/../data/chain7.json|--json${_ri_extra}" -DEXPECT_RC=0
                     "-DEXPECT_STDOUT=\"swept\": true&&${_ri_kept}"
                     "-DSTDOUT_FILE=${CMAKE_CURRENT_BINARY_DIR}/cli_solve_chain7_consistency_${_ri_consistency}.json"
                     "-DCHECK_PROGRAM=$<TARGET_FILE:solve_json_check>"
                     "-DCHECK_ARGS=STDOUT_FILE|${CMAKE_CURRENT_LIST_DIR}/../data/chain7.json|--complete|true|--solutions|2"
                     -P ${_ri_cli_script})
  endforeach()
  # analyze on a chain of 16 (32,768 chart combinations): the work read off the tree of hinges,
  # the sweep said, nothing expanded (its closing distance would have 3^15 terms: analyze once
  # ran for minutes and gigabytes on it)
  add_test(NAME cli_analyze_chain16_sweep
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=analyze|${CMAKE_CURRENT_LIST_DIR}/../data/chain16.json" -DEXPECT_RC=0
                   "-DEXPECT_STDOUT=32768 chart combinations x 1 placement combination&&solved along the tree by one sweep driven by"
                   -P ${_ri_cli_script})
  set_tests_properties(cli_analyze_chain16_sweep PROPERTIES TIMEOUT 60)
  # a chain of 64 tetrahedra (2^64 chart combinations: a count that once saturated to 0, so the
  # solve expanded the reduced system and hung past its time limit and SIGTERM): swept, and cut
  # by the time limit with the rest pending (the incidence tree's search takes about 10 s)
  add_test(NAME cli_solve_chain64_sweeps
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve|${CMAKE_CURRENT_LIST_DIR}/../data/chain64.json|--max-seconds|1|--json|--quiet"
                   -DEXPECT_RC=0 "-DEXPECT_STDOUT=\"complete\": false&&\"swept\": true&&time limit of 1 s"
                   -P ${_ri_cli_script})
  set_tests_properties(cli_solve_chain64_sweeps PROPERTIES TIMEOUT 90)
  add_test(NAME cli_solve_chain7_consistency_text
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve|${CMAKE_CURRENT_LIST_DIR}/../data/chain7.json" -DEXPECT_RC=0
                   "-DEXPECT_STDOUT=solved along the tree by a sweep \\(no chart combination built\\), arc consistency kept [0-9.e-]+ to [0-9.e-]+ % of each hinge's circle"
                   -P ${_ri_cli_script})
  add_test(NAME cli_usage_max_listed
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve|${_ri_platforms}|--max-listed|-2" -DEXPECT_RC=1
                   "-DEXPECT_STDERR=--max-listed: '-2' is not a whole number" -P ${_ri_cli_script})
  add_test(NAME cli_solve_platforms2_no_plan
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve|${_ri_platforms}|--no-plan|--max-seconds|3|--json" -DEXPECT_RC=0
                   "-DEXPECT_STDOUT=\"complete\": false&&\"planned_systems\": 0&&time limit of 3 s"
                   -P ${_ri_cli_script})
  add_test(NAME cli_usage_no_plan_analyze
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=analyze|${_ri_platforms}|--no-plan" -DEXPECT_RC=1
                   "-DEXPECT_STDERR=--no-plan is an option of solve and solve-system" -P ${_ri_cli_script})
  # a time limit for the whole solve, and the interrupt (issue 28, item 5): a scene whose solve
  # chart combination by chart combination (--no-sweep: the sweep solves it in a second;
  # --no-consistency: arc consistency leaves 2 of its 512 combinations, 2 s) runs
  # for 70 s (a chain of 10 tetrahedra) stops, and its partial answer is valid JSON whose solutions hold
  # in the scene and which says it is not complete (exit status 0 at the time limit, 130 or
  # 143 after SIGINT or SIGTERM, sent by coreutils' timeout)
  set(_ri_long ${CMAKE_CURRENT_LIST_DIR}/../data/tetrahedron_chain10.json)
  add_test(NAME cli_solve_max_seconds
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve|${_ri_long}|--no-sweep|--no-consistency|--json|--max-seconds|2" -DEXPECT_RC=0
                   "-DEXPECT_STDOUT=time limit of 2 s reached"
                   "-DSTDOUT_FILE=${CMAKE_CURRENT_BINARY_DIR}/cli_solve_max_seconds.json"
                   "-DCHECK_PROGRAM=$<TARGET_FILE:solve_json_check>" "-DCHECK_ARGS=STDOUT_FILE|${_ri_long}|--complete|false"
                   -P ${_ri_cli_script})
  add_test(NAME cli_solve_max_seconds_text
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve|${_ri_long}|--no-sweep|--no-consistency|--max-seconds|1|--quiet" -DEXPECT_RC=0
                   "-DEXPECT_STDOUT=limit reached: time limit of 1 s reached&&NOT complete" -P ${_ri_cli_script})
  find_program(RIGID_INCIDENCE_TIMEOUT timeout)
  if(RIGID_INCIDENCE_TIMEOUT)
    foreach(_sig INT TERM)
      if(_sig STREQUAL "INT")
        set(_rc 130)
      else()
        set(_rc 143)
      endif()
      add_test(NAME cli_solve_sig${_sig}
               COMMAND ${CMAKE_COMMAND} "-DTOOL=${RIGID_INCIDENCE_TIMEOUT}"
                       "-DARGS=--preserve-status|-s|${_sig}|3|${_ri_tool}|solve|${_ri_long}|--no-sweep|--no-consistency|--json" -DEXPECT_RC=${_rc}
                       "-DEXPECT_STDOUT=\"interrupted after"
                       "-DSTDOUT_FILE=${CMAKE_CURRENT_BINARY_DIR}/cli_solve_sig${_sig}.json"
                       "-DCHECK_PROGRAM=$<TARGET_FILE:solve_json_check>" "-DCHECK_ARGS=STDOUT_FILE|${_ri_long}|--complete|false"
                       -P ${_ri_cli_script})
    endforeach()
  endif()
  # (a limit that failed to stop the solve would run for minutes: fail after 5)
  foreach(_t cli_solve_max_seconds cli_solve_max_seconds_text)
    set_tests_properties(${_t} PROPERTIES TIMEOUT 300)
  endforeach()
  if(RIGID_INCIDENCE_TIMEOUT)
    set_tests_properties(cli_solve_sigINT cli_solve_sigTERM PROPERTIES TIMEOUT 300)
  endif()
  # SIGTERM sent twice at once (as GNU timeout does, to the tool and then to its process
  # group): one request, the partial answer still comes (CI once saw the second one end the
  # tool with nothing printed)
  find_program(RIGID_INCIDENCE_SH sh)
  if(RIGID_INCIDENCE_SH)
    add_test(NAME cli_solve_sigTERM_twice
             COMMAND ${CMAKE_COMMAND} "-DTOOL=${RIGID_INCIDENCE_SH}"
                     "-DARGS=${CMAKE_CURRENT_LIST_DIR}/../cli/signal_twice.sh|TERM|2|${_ri_tool}|solve|${_ri_long}|--no-sweep|--no-consistency|--json"
                     -DEXPECT_RC=143 "-DEXPECT_STDOUT=\"interrupted after"
                     "-DSTDOUT_FILE=${CMAKE_CURRENT_BINARY_DIR}/cli_solve_sigTERM_twice.json"
                     "-DCHECK_PROGRAM=$<TARGET_FILE:solve_json_check>" "-DCHECK_ARGS=STDOUT_FILE|${_ri_long}|--complete|false"
                     -P ${_ri_cli_script})
    set_tests_properties(cli_solve_sigTERM_twice PROPERTIES TIMEOUT 300)
  endif()
  # exact decisions that would take over 20 minutes (one CORE sign of a zero in a tower over
  # long rationals) stop after maximal_exact_seconds: the answer comes, not complete, and says
  # why; its configurations hold in the scene
  set(_ri_exact ${CMAKE_CURRENT_LIST_DIR}/../data/exact_decisions_stopped.json)
  add_test(NAME cli_solve_exact_decisions_stopped
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve|${_ri_exact}|--json" -DEXPECT_RC=0
                   "-DEXPECT_STDOUT=were stopped after 10 s \\(maximal_exact_seconds\\)"
                   "-DSTDOUT_FILE=${CMAKE_CURRENT_BINARY_DIR}/cli_solve_exact_decisions_stopped.json"
                   "-DCHECK_PROGRAM=$<TARGET_FILE:solve_json_check>" "-DCHECK_ARGS=STDOUT_FILE|${_ri_exact}|--complete|false"
                   -P ${_ri_cli_script})
  set_tests_properties(cli_solve_exact_decisions_stopped PROPERTIES TIMEOUT 300)
  # one exact sign that runs for minutes inside one step (no clock is checked in it): the
  # child process of the exact decisions is killed at the limit
  set(_ri_sign ${CMAKE_CURRENT_LIST_DIR}/../data/exact_sign_stopped.json)
  add_test(NAME cli_solve_exact_sign_stopped
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve|${_ri_sign}|--json" -DEXPECT_RC=0
                   "-DEXPECT_STDOUT=were stopped after 10 s \\(maximal_exact_seconds\\)"
                   "-DSTDOUT_FILE=${CMAKE_CURRENT_BINARY_DIR}/cli_solve_exact_sign_stopped.json"
                   "-DCHECK_PROGRAM=$<TARGET_FILE:solve_json_check>" "-DCHECK_ARGS=STDOUT_FILE|${_ri_sign}|--complete|false"
                   -P ${_ri_cli_script})
  set_tests_properties(cli_solve_exact_sign_stopped PROPERTIES TIMEOUT 300)
  # SIGTERM during those exact decisions: the child is killed at once (the wait looks at the
  # solve's interrupt), the partial answer comes in a second, not after the 10 s of the limit
  # (the test's TIMEOUT of 8 s fails otherwise)
  if(RIGID_INCIDENCE_TIMEOUT)
    add_test(NAME cli_solve_sigTERM_exact_decisions
             COMMAND ${CMAKE_COMMAND} "-DTOOL=${RIGID_INCIDENCE_TIMEOUT}"
                     "-DARGS=--preserve-status|-s|TERM|3|${_ri_tool}|solve|${_ri_sign}|--json" -DEXPECT_RC=143
                     "-DEXPECT_STDOUT=\"interrupted after"
                     "-DSTDOUT_FILE=${CMAKE_CURRENT_BINARY_DIR}/cli_solve_sigTERM_exact_decisions.json"
                     "-DCHECK_PROGRAM=$<TARGET_FILE:solve_json_check>" "-DCHECK_ARGS=STDOUT_FILE|${_ri_sign}|--complete|false"
                     -P ${_ri_cli_script})
    set_tests_properties(cli_solve_sigTERM_exact_decisions PROPERTIES TIMEOUT 8)
  endif()
  add_test(NAME cli_usage_max_seconds_negative
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve|${_ri_d}/tetra.json|--max-seconds|-1" -DEXPECT_RC=1
                   "-DEXPECT_STDERR=--max-seconds: '-1' is not a positive number" -P ${_ri_cli_script})
  add_test(NAME cli_usage_max_seconds_analyze
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=analyze|${_ri_d}/tetra.json|--max-seconds|1" -DEXPECT_RC=1
                   "-DEXPECT_STDERR=--max-seconds is an option of solve" -P ${_ri_cli_script})
  # --threads: a whole number of threads, for solve and solve-system; the JSON says how many ran
  # (tetra's 4 configurations with 2, checked as any solve)
  add_test(NAME cli_usage_threads_zero
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve|${_ri_d}/tetra.json|--threads|0" -DEXPECT_RC=1
                   "-DEXPECT_STDERR=--threads: '0' is not a positive number" -P ${_ri_cli_script})
  add_test(NAME cli_usage_threads_fraction
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve|${_ri_d}/tetra.json|--threads|1.5" -DEXPECT_RC=1
                   "-DEXPECT_STDERR=--threads: '1.5' is not a whole number of threads" -P ${_ri_cli_script})
  add_test(NAME cli_usage_threads_analyze
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=analyze|${_ri_d}/tetra.json|--threads|2" -DEXPECT_RC=1
                   "-DEXPECT_STDERR=--threads is an option of solve and solve-system" -P ${_ri_cli_script})
  add_test(NAME cli_solve_threads
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve|${_ri_d}/tetra.json|--json|--threads|2" -DEXPECT_RC=0
                   "-DEXPECT_STDOUT=\"threads\": [12]"
                   "-DSTDOUT_FILE=${CMAKE_CURRENT_BINARY_DIR}/cli_solve_threads.json"
                   "-DCHECK_PROGRAM=$<TARGET_FILE:solve_json_check>" "-DCHECK_ARGS=STDOUT_FILE|${_ri_d}/tetra.json|--complete|true|--solutions|4"
                   -P ${_ri_cli_script})
  # a scene that turns freely about an axis of three points, which the dof count calls rigid:
  # diagnosed, not refused (trace_curves took 0 equations in 1 variable for an error)
  add_test(NAME cli_solve_free_turn_about_axis
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve|${CMAKE_CURRENT_LIST_DIR}/../data/free_turn_about_axis.json|--json" -DEXPECT_RC=0
                   "-DSTDOUT_FILE=${CMAKE_CURRENT_BINARY_DIR}/cli_solve_free_turn_about_axis.json"
                   "-DCHECK_PROGRAM=$<TARGET_FILE:solve_json_check>"
                   "-DCHECK_ARGS=STDOUT_FILE|${CMAKE_CURRENT_LIST_DIR}/../data/free_turn_about_axis.json|--complete|false|--diagnosis|positive_dimensional"
                   -P ${_ri_cli_script})
  add_test(NAME cli_solve_text
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve|${_ri_d}/tetra.json" -DEXPECT_RC=0
                   "-DEXPECT_STDOUT=4 configuration\\(s\\), all certified: complete&&configuration 4: certified&&statistics: "
                   -P ${_ri_cli_script})
  add_test(NAME cli_solve_fast
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve|${_ri_d}/pent.json|--fast|--json" -DEXPECT_RC=0
                   "-DSTDOUT_FILE=${CMAKE_CURRENT_BINARY_DIR}/cli_solve_pent_fast.json"
                   "-DCHECK_PROGRAM=$<TARGET_FILE:solve_json_check>" "-DCHECK_ARGS=STDOUT_FILE|${_ri_d}/pent.json|--solutions|8|--certified|0|--complete|false"
                   -P ${_ri_cli_script})
  add_test(NAME cli_solve_svg
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve|${_ri_d}/tetra.json|--svg|${CMAKE_CURRENT_BINARY_DIR}/cli_tetra.svg" -DEXPECT_RC=0
                   "-DCHECK_FILE=${CMAKE_CURRENT_BINARY_DIR}/cli_tetra.svg"
                   "-DCHECK_FILE_REGEX=^<svg&&4 configuration\\(s\\), complete&&#4 certified&&<line x1=\"[0-9]+\\.[0-9][0-9]\"&&<circle&&</svg>" -P ${_ri_cli_script})
  add_test(NAME cli_solve_near
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve|${_ri_d}/pent.json|--near|${CMAKE_CURRENT_LIST_DIR}/../data/pent_near.json" -DEXPECT_RC=0
                   "-DEXPECT_STDOUT=configuration 1: certified[^\n]*\n  parameters: c1.t in [^\n]* c4.t in \\[-0.5257311121, [^\n]* c2.s in \\[0.5877852523" -P ${_ri_cli_script})
  add_test(NAME cli_solve_bad_tolerance
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve|${_ri_d}/tetra.json|--tolerance|-1" -DEXPECT_RC=1
                   "-DEXPECT_STDERR=--tolerance: '-1' is not a positive number" -P ${_ri_cli_script})
  add_test(NAME cli_solve_bad_precision
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve|${_ri_d}/tetra.json|--precision|12.5" -DEXPECT_RC=1
                   "-DEXPECT_STDERR=--precision: '12.5' is not a number of bits" -P ${_ri_cli_script})
  add_test(NAME cli_solve_option_of_analyze
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=analyze|${_ri_d}/tetra.json|--fast" -DEXPECT_RC=1
                   "-DEXPECT_STDERR=--fast is an option of solve" -P ${_ri_cli_script})
  add_test(NAME cli_solve_missing_scene
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve|${CMAKE_CURRENT_BINARY_DIR}/no_such_scene.json" -DEXPECT_RC=2
                   "-DEXPECT_STDERR=rigid_incidence: error: .*no_such_scene.json" -P ${_ri_cli_script})
  add_test(NAME cli_solve_bad_near
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve|${_ri_d}/tetra.json|--near|${_ri_d}/tetra.json" -DEXPECT_RC=2
                   "-DEXPECT_STDERR=expected \\{\"points\"" -P ${_ri_cli_script})
  # one degree of freedom: the scene moves, its configurations come as curves
  add_test(NAME cli_solve_one_dof_curves
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve|${_ri_d}/quad_one_dof.json|--json" -DEXPECT_RC=0
                   "-DEXPECT_STDOUT=\"complete\": true&&\"curves\": .\n +.\n +\"certified\": true,\n +\"closed\": true,&&\"E1\": .\n +.\n&&\"pieces\": &&\"curve_boxes\": [1-9]"
                   -P ${_ri_cli_script})
  add_test(NAME cli_solve_one_dof_svg
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve|${_ri_d}/quad_one_dof.json|--svg|${CMAKE_CURRENT_BINARY_DIR}/cli_quad_one_dof.svg|--plot|E1.x,E1.z" -DEXPECT_RC=0
                   "-DEXPECT_STDOUT=4 curve branch\\(es\\) of configurations&&branch 1 \\(certified\\): [0-9]+ frames in [0-9]+ chart piece\\(s\\), closed"
                   "-DCHECK_FILE=${CMAKE_CURRENT_BINARY_DIR}/cli_quad_one_dof.svg"
                   "-DCHECK_FILE_REGEX=^<svg&&4 curve branch&&branch 4, certified, closed&&<polyline&&E1.x from" -P ${_ri_cli_script})
  add_test(NAME cli_solve_bad_plot
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve|${_ri_d}/quad_one_dof.json|--svg|${CMAKE_CURRENT_BINARY_DIR}/cli_bad_plot.svg|--plot|Q9.x,E1.z" -DEXPECT_RC=2
                   "-DEXPECT_STDERR=--plot: no placed point 'Q9'" -P ${_ri_cli_script})
  # a family: the quad with its apex distance E1-E2 free (issue 7)
  add_test(NAME cli_family_quad
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=family|${_ri_d}/quad_family.json|--svg|${CMAKE_CURRENT_BINARY_DIR}/cli_quad_family.svg|--samples|4" -DEXPECT_RC=0
                   "-DEXPECT_STDOUT=free distance E1-E2 over .1, 8.&&2 branch\\(es\\), 16 fold\\(s\\), all certified: complete&&E1-E2 in .3.99774[0-9]*, 3.99774[0-9]*.: .4 \\(2 folds at this length\\)&&\\(3.99774[0-9]*, 4.36074[0-9]*\\): 16
&&\\(6.25352[0-9]*, 8\\): 0
&&branch 2 \\(certified\\): [0-9]+ frames in [0-9]+ chart piece\\(s\\), closed"
                   "-DCHECK_FILE=${CMAKE_CURRENT_BINARY_DIR}/cli_quad_family.svg"
                   "-DCHECK_FILE_REGEX=^<svg&&2 branch\\(es\\), 16 fold\\(s\\), complete&&branch 2 \\(certified\\), closed&&E1-E2 = 3.6: 4<&&c1: rotation since the first frame&&<path d=\" M&&</svg>" -P ${_ri_cli_script})
  add_test(NAME cli_family_json
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=family|${_ri_d}/quad_family.json|--json" -DEXPECT_RC=0
                   "-DEXPECT_STDOUT=\"complete\": true&&\"folds\": &&\"change\": -4&&\"counts\": &&\"count\": 16&&\"branches\": &&\"lengths\": &&\"fold_boxes\": [1-9]"
                   -P ${_ri_cli_script})
  add_test(NAME cli_family_default_range
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=family|${CMAKE_CURRENT_LIST_DIR}/../data/quad_family_no_range.json" -DEXPECT_RC=0
                   "-DEXPECT_STDOUT=over .0, 30. \\(no range given&&2 branch\\(es\\), 16 fold\\(s\\), all certified: complete&&\\(6.25352[0-9]*, 30\\): 0
"
                   -P ${_ri_cli_script})
  add_test(NAME cli_family_no_free_distance
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=family|${_ri_d}/quad_distinct.json" -DEXPECT_RC=2
                   "-DEXPECT_STDERR=declares no free distance" -P ${_ri_cli_script})
  add_test(NAME cli_family_bad_samples
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=family|${_ri_d}/quad_family.json|--samples|0" -DEXPECT_RC=1
                   "-DEXPECT_STDERR=--samples: '0' is not a positive number" -P ${_ri_cli_script})
  add_test(NAME cli_family_option_of_solve
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=family|${_ri_d}/quad_family.json|--plot|E1.x,E1.y" -DEXPECT_RC=1
                   "-DEXPECT_STDERR=--plot is an option of solve" -P ${_ri_cli_script})
  add_test(NAME cli_solve_free_distance
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve|${_ri_d}/quad_family.json" -DEXPECT_RC=0
                   "-DEXPECT_STDERR=E1-E2 is declared free: solved without it"
                   "-DEXPECT_STDOUT=0 configuration\\(s\\) and 2 curve branch\\(es\\), all certified: complete" -P ${_ri_cli_script})
  # a scene far from unit size (issue 27, item 6): solved at unit size, exactly scaled by a power
  # of two, and given back at its own scale; tetra's four configurations at 1e55 and 1e-55
  foreach(_x 1e55 1e-55)
    add_test(NAME cli_solve_tetra_x${_x}
             COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve|${CMAKE_CURRENT_LIST_DIR}/../data/solve_tetra_x${_x}.json" -DEXPECT_RC=0
                     "-DEXPECT_STDOUT=solved scaled by 2\\^&&4 configuration\\(s\\), all certified: complete&&P12 = \\(-1e[+-]55, 1e[+-]55, 1e[+-]55\\)&&relative to the scene's size ([0-9.]+e-1[0-9]|0)\\)"
                     -P ${_ri_cli_script})
  endforeach()
  add_test(NAME cli_solve_under_constrained
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve|${_ri_d}/bar_end.json|--json" -DEXPECT_RC=0
                   "-DEXPECT_STDOUT=\"complete\": false&&\"diagnosis\": \"under_constrained: " -P ${_ri_cli_script})
endif()

# --- solve-system: a polynomial system in PHCpack's format plus box and inequality lines (issue
# 7), solved along its solution plan. The parallelogram with a diagonal of van Sosin and Elber
# (Section 4): 4 real solutions, 1 with the two inequalities; the values are the paper's.
if(TARGET rigid_incidence)
  set(_ri_sys ${RIGID_INCIDENCE_DATA_DIR}/systems)
  # coefficients beyond the double range (issue 27, item 7): each equation is scaled by an
  # exact power of two, so 1e400 x - 1e400 is x = 1, not "positive-dimensional"
  add_test(NAME cli_solve_system_scaled_1e400
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve-system|${CMAKE_CURRENT_LIST_DIR}/../data/system_scaled_1e400.txt"
                   -DEXPECT_RC=0 "-DEXPECT_STDOUT=1 real root\\(s\\) in the box, 1 certified; complete&&1 certified: x = 1[^0-9.]" -P ${_ri_cli_script})
  add_test(NAME cli_solve_system_scaled_mixed
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve-system|${CMAKE_CURRENT_LIST_DIR}/../data/system_scaled_mixed.txt"
                   -DEXPECT_RC=0 "-DEXPECT_STDOUT=2 real root\\(s\\) in the box, 2 certified; complete&&x = -2 y = -6&&x = 2 y = 6" -P ${_ri_cli_script})
  add_test(NAME cli_solve_system_parallelogram
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve-system|${_ri_sys}/parallelogram.txt" -DEXPECT_RC=0
                   "-DEXPECT_STDOUT=4 equations in 4 variables, well_constrained; 2 block\\(s\\), the largest solves 2&&block 0: solve equation 1, equation 2 for Ax, Ay\n&&block 1: solve equation 3, equation 4 for Bx, By given Ax, Ay&&4 real root\\(s\\) in the box, 4 certified; complete&&Ax = -1.36[0-9]* Ay = 0.8248[0-9]* Bx = 0.64[0-9]* By = 0.8248"
                   -P ${_ri_cli_script})
  add_test(NAME cli_solve_system_parallelogram_inequalities
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve-system|${_ri_sys}/parallelogram_ineq.txt" -DEXPECT_RC=0
                   "-DEXPECT_STDOUT=2 inequalities&&1 real root\\(s\\) in the box, 1 certified; complete&&1 certified: Ax = -1.36[0-9]* Ay = 0.8248[0-9]* Bx = 0.64[0-9]* By = 0.8248"
                   -P ${_ri_cli_script})
  add_test(NAME cli_solve_system_no_plan
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve-system|${_ri_sys}/parallelogram.txt|--no-plan" -DEXPECT_RC=0
                   "-DEXPECT_STDOUT=4 real root\\(s\\) in the box, 4 certified; complete&&stats: 1 block solve" -P ${_ri_cli_script})
  add_test(NAME cli_solve_system_json
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve-system|${_ri_sys}/parallelogram_ineq.txt|--json" -DEXPECT_RC=0
                   "-DEXPECT_STDOUT=\"structure\": \"well_constrained\"&&\"blocks\": &&\"Ax\",&&\"complete\": true&&\"certified\": true&&\"curves\": &&\"block_solves\": 2"
                   -P ${_ri_cli_script})
  add_test(NAME cli_solve_system_dot
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve-system|${_ri_sys}/parallelogram.txt|--dot|${CMAKE_CURRENT_BINARY_DIR}/cli_plan.dot" -DEXPECT_RC=0
                   "-DCHECK_FILE=${CMAKE_CURRENT_BINARY_DIR}/cli_plan.dot"
                   "-DCHECK_FILE_REGEX=^digraph plan&&subgraph cluster_0&&subgraph cluster_1&&style=bold" -P ${_ri_cli_script})
  add_test(NAME cli_solve_system_missing_file
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve-system|${CMAKE_CURRENT_BINARY_DIR}/no_such_system.txt" -DEXPECT_RC=2
                   "-DEXPECT_STDERR=rigid_incidence: error: .*no_such_system.txt" -P ${_ri_cli_script})
  # an equation whose dense Bernstein array would not fit (3^20 coefficients): refused with a
  # message naming it, exit 2, instead of an aborted allocation
  add_test(NAME cli_solve_system_too_large
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve-system|${CMAKE_CURRENT_LIST_DIR}/../data/system_too_large.txt" -DEXPECT_RC=2
                   "-DEXPECT_STDERR=rigid_incidence: error: &&maximal_coefficients&&the largest is equation 1 in x0\\^2, x1\\^2&&3.49e\\+09 coefficients by itself"
                   -P ${_ri_cli_script})
  # one equation fewer than variables: the paper's four-bar linkage (Fig. 5) as curves; a
  # parallelogram linkage, so its two circuits cross at two singular points
  add_test(NAME cli_solve_system_four_bar
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve-system|${_ri_sys}/four_bar_linkage.txt" -DEXPECT_RC=0
                   "-DEXPECT_STDOUT=one_degree_of_freedom&&the solution set is a curve, traced as a whole; NOT complete&&4 curve branch\\(es\\), 4 with certified topology; 2 unresolved region\\(s\\)&&branch 1 \\(certified\\): [0-9]+ points, from unresolved to unresolved&&unresolved \\(unknown\\): singular"
                   -P ${_ri_cli_script})
  add_test(NAME cli_solve_system_four_bar_inequalities
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve-system|${_ri_sys}/four_bar_linkage_ineq.txt|--json" -DEXPECT_RC=0
                   "-DEXPECT_STDOUT=\"structure\": \"one_degree_of_freedom\"&&\"complete\": false&&\"curves\": .\n +.\n +\"certified\": true,\n +\"closed\": false,\n +\"ends\": .\n +\"unresolved\",\n +\"unresolved\"&&\"points\": .&&\"face_solves\": [1-9]"
                   -P ${_ri_cli_script})
  # Jansen's linkage with its five inequalities, traced along its plan (the crank, then one
  # point at a time): the physical leg, one certified closed branch
  add_test(NAME cli_solve_system_jansen_inequalities
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve-system|${_ri_sys}/jansen_ineq.txt" -DEXPECT_RC=0
                   "-DEXPECT_STDOUT=one_degree_of_freedom&&the solution set is a curve, traced along the plan .block 1, then the others lifted over it.; complete&&1 curve branch\\(es\\), 1 with certified topology; 0 unresolved region\\(s\\)&&branch 1 \\(certified\\): [0-9]+ points, closed"
                   -P ${_ri_cli_script})
  add_test(NAME cli_solve_system_jansen_inequalities_json
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve-system|${_ri_sys}/jansen_ineq.txt|--json" -DEXPECT_RC=0
                   "-DEXPECT_STDOUT=\"complete\": true&&\"curves\": .\n +.\n +\"certified\": true,\n +\"closed\": true&&\"curve_traced_along_plan\": true&&\"block_solves\": [1-9]"
                   -P ${_ri_cli_script})
  add_test(NAME cli_solve_system_rejects_svg
           COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve-system|${_ri_sys}/parallelogram.txt|--svg|x.svg" -DEXPECT_RC=1
                   "-DEXPECT_STDERR=--svg is an option of solve" -P ${_ri_cli_script})
endif()

# --- solve-system on systems of PHCpack's demo database (src/Demo of janverschelde/PHCpack):
# the real roots in the box each file states must all be found and certified. The expected roots
# (data/systems/phcpack/NAME.roots.json) come from the solution list the PHCpack file ships,
# cross-checked by `phc -b` (see examples/Rigid_incidence/data/systems/phcpack/README.md);
# system_json_check matches the solutions to them one to one. About 5 s together in Release, 45 s
# with the sanitizers.
if(TARGET rigid_incidence)
  add_executable(system_json_check ${CMAKE_CURRENT_LIST_DIR}/../system_json_check.cpp)
  ri_test_flags(system_json_check)
  target_link_libraries(system_json_check PRIVATE nlohmann_json::nlohmann_json)
  set(_ri_phc ${RIGID_INCIDENCE_DATA_DIR}/systems/phcpack)
  set(_ri_phc_systems caprasse_new chandra4 chemequ cyclic5 eco5 fourbar game4two katsura5 lorentz rbpl rediff3 sendra)
  # the three slowest (about 1.2 s each in Release, ten times that with the sanitizers) only in
  # the plain build: the sanitizers see the same code on the others
  if(NOT RIGID_INCIDENCE_SANITIZE)
    list(APPEND _ri_phc_systems geneig kotsireas tangents2)
  endif()
  foreach(_s ${_ri_phc_systems})
    add_test(NAME cli_solve_system_phcpack_${_s}
             COMMAND ${CMAKE_COMMAND} "-DTOOL=${_ri_tool}" "-DARGS=solve-system|${_ri_phc}/${_s}.txt|--json" -DEXPECT_RC=0
                     "-DSTDOUT_FILE=${CMAKE_CURRENT_BINARY_DIR}/cli_solve_system_phcpack_${_s}.json"
                     "-DCHECK_PROGRAM=$<TARGET_FILE:system_json_check>" "-DCHECK_ARGS=STDOUT_FILE|${_ri_phc}/${_s}.roots.json"
                     -P ${_ri_cli_script})
  endforeach()
endif()
