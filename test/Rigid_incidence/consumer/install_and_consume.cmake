# Copyright (c) 2026 Rigid_incidence contributors.
# SPDX-License-Identifier: LGPL-3.0-or-later
#
# Run by the ctest install_and_consume (see ../cmake/install_consumer.cmake):
#   cmake -DMAIN_BUILD_DIR=... -DPREFIX=... -DCONSUMER_SOURCE_DIR=... -DCONSUMER_BUILD_DIR=...
#         -DPACKAGE_SOURCE_DIR=... -DSCENE=... [-DCONFIG=...] [-DGENERATOR=...] [-DCXX_COMPILER=...]
#         [-DEXPECTED_WEIGHT=3] -P install_and_consume.cmake
# 1. cmake --install MAIN_BUILD_DIR into PREFIX (emptied first);
# 2. configure CONSUMER_SOURCE_DIR in CONSUMER_BUILD_DIR (emptied first) with
#    CMAKE_PREFIX_PATH=PREFIX and the package registries off, check that the package was
#    found in PREFIX and that the consumer compiles against PREFIX/include, not the sources;
# 3. build it and run it on SCENE; it checks the incidence tree weight (EXPECTED_WEIGHT).
cmake_minimum_required(VERSION 3.14)

foreach(v MAIN_BUILD_DIR PREFIX CONSUMER_SOURCE_DIR CONSUMER_BUILD_DIR PACKAGE_SOURCE_DIR SCENE)
  if(NOT DEFINED ${v} OR "${${v}}" STREQUAL "")
    message(FATAL_ERROR "install_and_consume: -D${v}=... is required")
  endif()
endforeach()
if(NOT DEFINED EXPECTED_WEIGHT)
  set(EXPECTED_WEIGHT 3)
endif()
if(NOT CONFIG)
  set(CONFIG Release)
endif()

function(run_step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "install_and_consume: ${what} failed (${rc}):\n${out}\n${err}")
  endif()
  message(STATUS "install_and_consume: ${what}: ok")
  set(step_output "${out}" PARENT_SCOPE)
endfunction()

# 1. install
file(REMOVE_RECURSE "${PREFIX}" "${CONSUMER_BUILD_DIR}")
run_step("cmake --install ${MAIN_BUILD_DIR} --prefix ${PREFIX}"
  ${CMAKE_COMMAND} --install "${MAIN_BUILD_DIR}" --prefix "${PREFIX}" --config "${CONFIG}")
file(GLOB_RECURSE config_file "${PREFIX}/*/Rigid_incidenceConfig.cmake")
if(NOT config_file OR NOT EXISTS "${PREFIX}/include/CGAL/Rigid_incidence.h")
  message(FATAL_ERROR "install_and_consume: the install into ${PREFIX} lacks Rigid_incidenceConfig.cmake "
                      "or include/CGAL/Rigid_incidence.h")
endif()

# 2. configure the consumer against the prefix only
set(configure_args -S "${CONSUMER_SOURCE_DIR}" -B "${CONSUMER_BUILD_DIR}"
  "-DCMAKE_PREFIX_PATH=${PREFIX}" "-DCMAKE_BUILD_TYPE=${CONFIG}" -DCMAKE_EXPORT_COMPILE_COMMANDS=ON
  -DCMAKE_FIND_PACKAGE_NO_PACKAGE_REGISTRY=ON -DCMAKE_FIND_PACKAGE_NO_SYSTEM_PACKAGE_REGISTRY=ON)
if(GENERATOR)
  list(APPEND configure_args -G "${GENERATOR}")
endif()
if(CXX_COMPILER)
  list(APPEND configure_args "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}")
endif()
run_step("configure the consumer" ${CMAKE_COMMAND} ${configure_args})

file(STRINGS "${CONSUMER_BUILD_DIR}/CMakeCache.txt" found_dir REGEX "^Rigid_incidence_DIR:")
string(REGEX REPLACE "^Rigid_incidence_DIR:[A-Z]*=" "" found_dir "${found_dir}")
get_filename_component(found_dir "${found_dir}" REALPATH)
get_filename_component(real_prefix "${PREFIX}" REALPATH)
string(FIND "${found_dir}/" "${real_prefix}/" at)
if(NOT at EQUAL 0)
  message(FATAL_ERROR "install_and_consume: find_package(Rigid_incidence) used ${found_dir}, "
                      "not the installed copy under ${real_prefix}")
endif()
message(STATUS "install_and_consume: package found in ${found_dir}")

# 3. build and run
run_step("build the consumer" ${CMAKE_COMMAND} --build "${CONSUMER_BUILD_DIR}" --config "${CONFIG}")

if(EXISTS "${CONSUMER_BUILD_DIR}/compile_commands.json")
  file(READ "${CONSUMER_BUILD_DIR}/compile_commands.json" commands)
  string(FIND "${commands}" "${PACKAGE_SOURCE_DIR}/include" in_sources)
  string(FIND "${commands}" "${PREFIX}/include" in_prefix)
  if(NOT in_sources EQUAL -1 OR in_prefix EQUAL -1)
    message(FATAL_ERROR "install_and_consume: the consumer must compile against ${PREFIX}/include "
                        "and not ${PACKAGE_SOURCE_DIR}/include:\n${commands}")
  endif()
endif()

find_program(consumer_exe consumer PATHS "${CONSUMER_BUILD_DIR}" "${CONSUMER_BUILD_DIR}/${CONFIG}"
             NO_DEFAULT_PATH)
if(NOT consumer_exe)
  message(FATAL_ERROR "install_and_consume: no consumer executable in ${CONSUMER_BUILD_DIR}")
endif()
run_step("run the consumer on ${SCENE}" "${consumer_exe}" "${SCENE}" "${EXPECTED_WEIGHT}")
message(STATUS "${step_output}")
string(FIND "${step_output}" "weight ${EXPECTED_WEIGHT} " has_weight)
if(has_weight EQUAL -1)
  message(FATAL_ERROR "install_and_consume: the consumer did not report weight ${EXPECTED_WEIGHT}")
endif()
message(STATUS "install_and_consume: OK")
