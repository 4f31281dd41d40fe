# Copyright (c) 2026 Rigid_incidence contributors.
# SPDX-License-Identifier: LGPL-3.0-or-later
#
# ctest install_and_consume: installs this build into a scratch prefix, then configures,
# builds and runs a separate project (test/Rigid_incidence/consumer) that finds the package
# with find_package(Rigid_incidence) from that prefix only. The work is done by the script
# consumer/install_and_consume.cmake (run with cmake -P); everything it makes lives under
# <build>/install_consumer and is recreated on each run.
set(RIGID_INCIDENCE_CONSUMER_WORK ${CMAKE_BINARY_DIR}/install_consumer)
add_test(NAME install_and_consume
  COMMAND ${CMAKE_COMMAND}
    -DMAIN_BUILD_DIR=${CMAKE_BINARY_DIR}
    -DCONFIG=$<CONFIG>
    -DPREFIX=${RIGID_INCIDENCE_CONSUMER_WORK}/prefix
    -DCONSUMER_SOURCE_DIR=${CMAKE_CURRENT_SOURCE_DIR}/consumer
    -DCONSUMER_BUILD_DIR=${RIGID_INCIDENCE_CONSUMER_WORK}/build
    -DPACKAGE_SOURCE_DIR=${PROJECT_SOURCE_DIR}
    "-DGENERATOR=${CMAKE_GENERATOR}"
    -DCXX_COMPILER=${CMAKE_CXX_COMPILER}
    -DSCENE=${RIGID_INCIDENCE_DATA_DIR}/tetra.json
    -DEXPECTED_WEIGHT=3
    -P ${CMAKE_CURRENT_SOURCE_DIR}/consumer/install_and_consume.cmake)
set_tests_properties(install_and_consume PROPERTIES TIMEOUT 300)
